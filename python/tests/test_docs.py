"""docs/python.md: its 2-Stack transfer runs as written and says what the page says (the pgmpy
round trip, which needs pgmpy, is run by test_pgmpy.py), and so does its heat map."""

from conftest import python_blocks

import pgm


def test_the_heat_map_example_runs_as_written(tmp_path, monkeypatch):
    import matplotlib

    matplotlib.use("Agg")
    monkeypatch.chdir(tmp_path)
    names = {}
    exec(compile(python_blocks("docs/python.md")[0], "docs/python.md", "exec"), names)
    assert (tmp_path / "onTop2.png").read_bytes().startswith(b"\x89PNG\r\n\x1a\n")
    assert names["figure"].axes[0].get_title() == "P(onTop2 = 1 | xOff2, yOff2, xOff1 = @2, yOff1 = @2)"


def test_the_two_stack_transfer_runs_as_written(capsys):
    blocks = python_blocks("docs/python.md")
    assert len(blocks) == 5
    names = {}
    exec(compile(blocks[1], "docs/python.md", "exec"), names)
    printed = capsys.readouterr().out.splitlines()
    mle_says, minimal_says = (float(x) for x in printed[0].split())
    assert mle_says == 0.5  # the page's comment: an unseen configuration
    assert minimal_says != 0.5
    assert names["advice"]["predicted_after"] >= 0.8  # prevention reaches epsilon
    assert set(names["advice"]["suggestion"]) == {"xOff2", "yOff2"}
    assert names["minimal"].notes == ["'onTop2' gets the minimal prior from 'onTop1' with w = 5"]
    assert isinstance(names["minimal"], pgm.Network)


def test_the_markov_network_example_runs_as_written(capsys):
    import math

    blocks = python_blocks("docs/python.md")
    names = {"pgm": pgm}
    exec(compile(blocks[3], "docs/python.md", "exec"), names)
    printed = capsys.readouterr().out.splitlines()
    assert float(printed[0]) == round(math.log(44), 6)
    assert printed[1] == str([round(4 / 34, 6), round(30 / 34, 6)])
    assert printed[2] == "{'a': '1', 'b': '1', 'c': '1'}"
    assert float(printed[3]) == round(math.log(34), 6)


def test_the_influence_diagram_example_runs_as_written(capsys, monkeypatch):
    from conftest import SOURCE_DIR

    monkeypatch.chdir(SOURCE_DIR)
    exec(compile(python_blocks("docs/python.md")[4], "docs/python.md", "exec"), {"pgm": pgm})
    printed = capsys.readouterr().out.splitlines()
    assert float(printed[0]) == 22.5
    assert printed[1] == str(
        [
            {"Test": "yes", "Seismic": "closed", "action": "yes"},
            {"Test": "yes", "Seismic": "open", "action": "yes"},
            {"Test": "yes", "Seismic": "diffuse", "action": "no"},
        ]
    )
    assert float(printed[2]) == 32.5
