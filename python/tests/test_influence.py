"""pgm.InfluenceDiagram: the published oil wildcatter read, solved and written back, its
policies as DataFrames, limited memory and the value of information."""

import pytest

import pgm
from conftest import SOURCE_DIR

OIL = SOURCE_DIR / "tests" / "data" / "decisions" / "oil_wildcatter.xml"


def test_the_oil_wildcatter_tests_and_drills_unless_the_sounding_is_diffuse():
    diagram = pgm.InfluenceDiagram.read(OIL)
    assert diagram.decisions == ["Test", "Drill"]
    assert diagram.utilities == ["TestCost", "Payoff"]
    solution = diagram.solve()
    assert solution.meu == pytest.approx(22.5, abs=1e-12)
    assert not solution.local_optimum
    assert solution.policies["Test"]["action"].tolist() == ["yes"]
    drill = solution.policies["Drill"]
    assert list(drill.columns) == ["Test", "Seismic", "action"]
    tested = drill[drill["Test"] == "yes"].set_index("Seismic")["action"]
    assert tested.to_dict() == {"closed": "yes", "open": "yes", "diffuse": "no"}


def test_limited_memory_evidence_and_information():
    diagram = pgm.InfluenceDiagram.read(OIL)
    limited = diagram.solve(limited_memory=True)
    assert limited.local_optimum and limited.meu == pytest.approx(22.5, abs=1e-12)
    assert limited.start_expected_utility < limited.meu
    # Known to be wet: drill without testing, 50.
    assert diagram.solve(evidence={"Oil": "wet"}).meu == pytest.approx(50, abs=1e-12)
    # Knowing the oil at the drill: 0.3·50 + 0.2·200 = 55, so 32.5 more than 22.5.
    assert diagram.value_of_information("Oil", before="Drill") == pytest.approx(32.5, abs=1e-12)


def test_bad_input_is_a_pgm_error(tmp_path):
    diagram = pgm.InfluenceDiagram.read(OIL)
    with pytest.raises(pgm.Error, match="'Seismic' depends on the decision 'Test'"):
        diagram.solve(evidence={"Seismic": "open"})
    with pytest.raises(pgm.Error, match="no state 'damp'"):
        diagram.solve(evidence={"Oil": "damp"})
    bad = tmp_path / "bad.xml"
    bad.write_text(OIL.read_text().replace("<FOR>Test</FOR>", "<FOR>Test</FOR><TABLE>0.5 0.5</TABLE>"))
    with pytest.raises(pgm.Error, match=r"bad.xml:\d+:\d+: .*the decision 'Test' has a <TABLE>"):
        pgm.InfluenceDiagram.read(bad)


def test_what_it_writes_reads_back(tmp_path):
    for name in ("oil.xml", "oil.json"):
        path = tmp_path / name
        pgm.InfluenceDiagram.read(OIL).write(path)
        assert pgm.InfluenceDiagram.read(path).solve().meu == pytest.approx(22.5, abs=1e-12)
    assert '"kind": "influence"' in (tmp_path / "oil.json").read_text()
