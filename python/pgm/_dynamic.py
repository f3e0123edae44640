"""Dynamic networks for Python: pgm.DynamicNetwork holds a two-slice temporal network (a first
slice, and a transition whose tables are tied across slices, their parents in the same slice or
the one before), read from pgm's JSON model of "kind": "dynamic" (docs/dynamic.md), and unrolls
it into a pgm.Network of T slices whose variables are named X@0 … X@(T−1)."""

from . import _core
from ._checks import _path, _whole


class DynamicNetwork:
    """A two-slice temporal Bayesian network: pgm.read_network returns one for a JSON model of
    "kind": "dynamic"."""

    __slots__ = ("_model",)

    def __init__(self, handle):
        if not isinstance(handle, _core.DynamicNetwork):
            raise TypeError("read a DynamicNetwork with pgm.read_network")
        self._model = handle

    @property
    def variables(self):
        """The template variables, in the first slice's order."""
        return self._model.variables

    def states(self, variable):
        return self._model.states(variable)

    @property
    def initial(self):
        """The first slice, a pgm.Network over the template variables."""
        from . import Network

        return Network(self._model.initial)

    @property
    def transition_edges(self):
        """The transition's edges: (parent, child), a parent named "X" (this slice) or "X@-1"."""
        return self._model.transition_edges

    def unroll(self, steps):
        """The pgm.Network of the first `steps` slices (at least 1), variables X@0 … X@(steps−1)."""
        from . import Network

        return Network(self._model.unroll(_whole(steps, "steps", 1, 1 << 20)))

    def write(self, path):
        """Writes the model as pgm's JSON ("kind": "dynamic"), atomically."""
        self._model.write(_path(path, "path"))

    def __repr__(self):
        return f"<pgm.DynamicNetwork: {len(self.variables)} template variables>"
