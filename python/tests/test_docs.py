"""docs/python.md: its 2-Stack transfer runs as written and says what the page says (the pgmpy
round trip, which needs pgmpy, is run by test_pgmpy.py)."""

from conftest import python_blocks

import pgm


def test_the_two_stack_transfer_runs_as_written(capsys):
    blocks = python_blocks("docs/python.md")
    assert len(blocks) == 2
    names = {}
    exec(compile(blocks[0], "docs/python.md", "exec"), names)
    printed = capsys.readouterr().out.splitlines()
    mle_says, minimal_says = (float(x) for x in printed[0].split())
    assert mle_says == 0.5  # the page's comment: an unseen configuration
    assert minimal_says != 0.5
    assert names["advice"]["predicted_after"] >= 0.8  # prevention reaches epsilon
    assert set(names["advice"]["suggestion"]) == {"xOff2", "yOff2"}
    assert names["minimal"].notes == ["'onTop2' gets the minimal prior from 'onTop1' with w = 5"]
    assert isinstance(names["minimal"], pgm.Network)
