"""docs/robot-loop.md: the robot loop runs as written, and learning by doing shows: each robot
ends better than it began, and the transferred prior starts it better than MLE."""

from conftest import python_blocks


def test_the_robot_loop_runs_as_written_and_the_success_rate_climbs(capsys):
    (block,) = python_blocks("docs/robot-loop.md")
    names = {}
    exec(compile(block, "docs/robot-loop.md", "exec"), names)
    table = names["table"]
    assert list(table.columns) == ["MLE", "Minimal-Replacement, w = 5"]
    assert len(table) == 6
    for name in table.columns:
        assert table[name].iloc[-1] > table[name].iloc[0], name
    assert table["Minimal-Replacement, w = 5"].iloc[0] > table["MLE"].iloc[0]
    assert "trials" in capsys.readouterr().out
