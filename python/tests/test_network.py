"""pgm.Network: reading and writing BIF and JSON, variables, states, parents and tables."""

import sys

import numpy as np
import pandas as pd
import pytest
from conftest import SOURCE_DIR, assert_same_network

import pgm

SACHS = SOURCE_DIR / "tests" / "data" / "networks" / "sachs.bif"


def test_read_a_published_network():
    net = pgm.read_network(SACHS)
    assert len(net.variables) == 11
    assert net.variables[0] == "Akt"
    assert net.states("Akt") == ["LOW", "AVG", "HIGH"]
    assert net.parents("Akt") == ["Erk", "PKA"]
    assert ("Erk", "Akt") in net.edges
    assert net.free_parameters == 178
    assert net.success is None


def test_a_table_has_one_row_per_configuration_last_parent_fastest():
    table = pgm.read_network(SACHS).cpt("Akt")
    assert list(table.columns) == ["Erk", "PKA", "LOW", "AVG", "HIGH"]
    assert len(table) == 9
    # sachs.bif lists (Erk, PKA) with Erk fastest; the frame has PKA fastest.
    assert list(table["Erk"][:4]) == ["LOW", "LOW", "LOW", "AVG"]
    assert list(table["PKA"][:4]) == ["LOW", "AVG", "HIGH", "LOW"]
    assert table.loc[1, "LOW"] == 0.62038586  # the file's (LOW, AVG) row
    assert table.loc[3, "HIGH"] == 0.0001796945  # the file's (AVG, LOW) row
    assert np.allclose(table[["LOW", "AVG", "HIGH"]].sum(axis=1), 1.0)


def test_a_root_table_has_one_row():
    table = pgm.read_network(SACHS).cpt("PKC")
    assert list(table.columns) == ["LOW", "AVG", "HIGH"]
    assert len(table) == 1


def test_write_and_read_back_every_format(tmp_path):
    net = pgm.read_network(SACHS)
    for name in ("sachs.json", "sachs.bif", "sachs.xml", "sachs.net"):
        net.write(tmp_path / name)
        assert_same_network(pgm.read_network(tmp_path / name), net)


def test_intervals_and_the_success_event_of_a_json_model(tmp_path):
    frame = pd.DataFrame({"x": [0, 1, 1, 0], "ok": [1, 0, 1, 1]})
    net = pgm.fit(frame, "x->ok", intervals={"x": [-1.0, 0.0, 1.0]})
    net.write(tmp_path / "m.json")
    text = (tmp_path / "m.json").read_text()
    (tmp_path / "m.json").write_text(text.replace('"format"', '"metadata": {"success": "ok=0"}, "format"', 1))
    back = pgm.read_network(tmp_path / "m.json")
    assert back.interval_edges("x") == [-1.0, 0.0, 1.0]
    assert back.success == "ok=0"
    assert pgm.predict(back, {"x": -0.5}) == 0.0  # P(ok=0 | x in bin 0)


def test_reading_errors_name_the_file_and_place(tmp_path):
    with pytest.raises(pgm.Error, match="missing.bif"):
        pgm.read_network(tmp_path / "missing.bif")
    (tmp_path / "bad.bif").write_text("network x {\n}\nvariable a {\n  type discrete [ 3 ] { 0, 1 };\n}\n")
    with pytest.raises(pgm.Error, match=r"bad\.bif:4:\d+"):
        pgm.read_network(tmp_path / "bad.bif")
    with pytest.raises(pgm.Error, match=r"expected one of \.bif, \.xml"):
        pgm.read_network(tmp_path / "net.txt")


def test_writing_needs_a_known_extension(tmp_path):
    with pytest.raises(pgm.Error, match=r"expected one of \.bif, \.xml"):
        pgm.read_network(SACHS).write(tmp_path / "net.txt")
    assert not (tmp_path / "net.txt").exists()


def test_unknown_variables_are_errors():
    net = pgm.read_network(SACHS)
    for call in (net.states, net.parents, net.cpt):
        with pytest.raises(pgm.Error, match="'Nope'"):
            call("Nope")


def test_networks_are_made_by_the_package():
    with pytest.raises(TypeError, match="pgm.read_network"):
        pgm.Network(None)
    assert repr(pgm.read_network(SACHS)) == "<pgm.Network: 11 variables, 17 edges, 178 free parameters>"


def test_pgmpy_conversions_say_that_pgmpy_is_missing(monkeypatch):
    monkeypatch.setitem(sys.modules, "pgmpy", None)
    monkeypatch.setitem(sys.modules, "pgmpy.models", None)
    with pytest.raises(ImportError, match="need pgmpy, which is not importable"):
        pgm.read_network(SACHS).to_pgmpy()
    with pytest.raises(ImportError, match="need pgmpy"):
        pgm.from_pgmpy(object())


def test_a_network_draws_itself_through_graphviz(tmp_path):
    net = pgm.fit(
        pd.DataFrame({"xOff2": [0, 1, 2, 0], "yOff2": [1, 1, 0, 2], "onTop2": [1, 0, 0, 1]}),
        "xOff2->onTop2,yOff2->onTop2",
    )
    dot = net.to_dot(success="onTop2", controllable=["xOff2", "yOff2"])
    assert '"onTop2" [label="onTop2\\n2 states", shape=doubleoctagon' in dot
    assert '"xOff2" [label="xOff2\\n3 states", shape=box' in dot
    svg = net._repr_svg_()
    assert svg.lstrip().startswith("<?xml") and "<svg" in svg
    for name in ("xOff2", "yOff2", "onTop2"):
        assert name in svg
    net.draw(tmp_path / "net.png", success="onTop2")
    assert (tmp_path / "net.png").read_bytes().startswith(b"\x89PNG\r\n\x1a\n")
    net.draw(tmp_path / "net.dot")
    assert (tmp_path / "net.dot").read_text().startswith("digraph network {")
    with pytest.raises(pgm.Error, match="expected a .svg, .png, .pdf or .dot file"):
        net.draw(tmp_path / "net.jpg")
    with pytest.raises(pgm.Error, match="'onTop3' is not a variable"):
        net.to_dot(success="onTop3")


def test_a_table_is_drawn_as_a_heat_map_with_the_table_s_numbers(tmp_path, program):
    import matplotlib

    matplotlib.use("Agg")
    random = np.random.default_rng(3)
    frame = pd.DataFrame({name: random.integers(0, 2, 300) for name in ("x", "y", "z")})
    frame["onTop"] = (random.random(300) < 0.2 + 0.2 * (frame.x + frame.y + frame.z)).astype(int)
    net = pgm.fit(frame, "x->onTop,y->onTop,z->onTop", keep_counts=True)
    figure = net.plot_table("onTop", "x", "y", given={"z": "1"}, counts=True, path=tmp_path / "t.png")
    (axes, colorbar) = figure.axes
    cells = axes.collections[0].get_array().reshape(2, 2)  # [y, x]
    table = net.cpt("onTop")
    for x in (0, 1):
        for y in (0, 1):
            row = table[(table.x == str(x)) & (table.y == str(y)) & (table.z == "1")]
            assert cells[y, x] == row["1"].item()
    texts = [t.get_text() for t in axes.texts]
    rows_at_1_1 = int(((frame.x == 1) & (frame.y == 1) & (frame.z == 1)).sum())
    assert f"{cells[1, 1]:.2f}\n{rows_at_1_1} rows" in texts
    assert axes.get_title() == "P(onTop = 1 | x, y, z = 1)"
    assert (tmp_path / "t.png").read_bytes().startswith(b"\x89PNG\r\n\x1a\n")
    # The program draws the same numbers.
    path = tmp_path / "m.json"
    net.write(path)
    program.run("plot-table", "--model", path, "--node", "onTop", "--x", "x", "--y", "y", "--given", "z=1",
                "--out", tmp_path / "t.gp")
    script = (tmp_path / "t.gp").read_text()
    block = script.split("$cells << EOD\n")[1].split("EOD\n")[0]
    drawn = {(float(c[0]), float(c[1])): float(c[6]) for c in (line.split() for line in block.splitlines())}
    assert drawn == {(x + 0.5, y + 0.5): cells[y, x] for x in (0, 1) for y in (0, 1)}
    averaged = net.plot_table("onTop", "x", "y", average=True, state="0", path=tmp_path / "a.svg")
    assert "others averaged" in averaged.axes[0].get_title()
    assert "<svg" in (tmp_path / "a.svg").read_text()
    with pytest.raises(pgm.Error, match=r"give z a state each \(e.g. z=0\), or average over them"):
        net.plot_table("onTop", "x", "y")
    with pytest.raises(pgm.Error, match="expected a .png, .svg or .pdf file"):
        net.plot_table("onTop", "x", "y", average=True, path=tmp_path / "t.jpg")
    assert not (tmp_path / "t.jpg").exists()
    with pytest.raises(pgm.Error, match="carries no counts"):
        pgm.fit(frame, "x->onTop,y->onTop,z->onTop").plot_table("onTop", "x", "y", average=True, counts=True)


def test_a_network_shows_itself_as_a_table_in_a_notebook():
    net = pgm.fit(
        pd.DataFrame({"xOff2": [0, 1, 2, 0], "yOff2": ["a", "b", "a", "<b>"], "onTop2": [1, 0, 0, 1]}),
        "xOff2->onTop2,yOff2->onTop2",
        keep_counts=True,
    )
    html = net._repr_html_()
    assert html.startswith("<p><b>pgm.Network</b>: 3 variables, 2 edges, 13 free parameters; it carries its counts")
    assert "<td><b>onTop2</b></td><td>0, 1</td><td>xOff2, yOff2</td><td style='text-align:right'>18</td>" in html
    assert "&lt;b&gt;" in html and "<b>b>" not in html  # state names are escaped


def test_plot_table_refuses_an_ax_that_is_no_axes():
    # Issue 49: ax="the axes" ended in an AttributeError from deep in the drawing.
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    net = pgm.fit(pd.DataFrame({"x": [0, 1, 1, 0], "y": [1, 1, 0, 0], "ok": [1, 0, 1, 1]}), "x->ok,y->ok")
    expected = r"^ax must be a matplotlib Axes \(e.g. from plt.subplots\(\)\) or None, got "
    for ax, kind in (("the axes", "str"), (Figure(), "Figure"), (3, "int")):
        with pytest.raises(TypeError, match=expected + kind + "$"):
            net.plot_table("ok", "x", "y", average=True, ax=ax)
    axes = Figure().add_subplot()
    assert net.plot_table("ok", "x", "y", average=True, ax=axes) is axes.figure


def test_empty_marks_mark_no_variable(tmp_path):
    # Issue 49: success=[] and controllable=[] were refused as empty; they mark no variable.
    frame = pd.DataFrame({"x": [0, 1, 1, 0], "ok": [1, 0, 1, 1]})
    pgm.fit(frame, "x->ok").write(tmp_path / "m.json")
    text = (tmp_path / "m.json").read_text()
    (tmp_path / "m.json").write_text(text.replace('"format"', '"metadata": {"success": "ok=1"}, "format"', 1))
    net = pgm.read_network(tmp_path / "m.json")
    assert "doubleoctagon" in net.to_dot()  # the success variable the model names
    assert "doubleoctagon" not in net.to_dot(success=[])
    assert net.to_dot(success=[]) == net.to_dot(success=[], controllable=())
    assert net.to_dot(controllable=[]) == net.to_dot()
