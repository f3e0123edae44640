"""Networks to and from pgmpy (internal; pgmpy is imported only here, when asked for).

Both sides number a table's parent configurations alike (last parent fastest), so a table
crosses as its array transposed: pgm keeps one row per configuration, pgmpy one per child
state. Interval edges and semantic tags have no place in a pgmpy model and stay behind.
"""

import numpy as np

from . import _core


def _pgmpy_models():
    try:
        import pgmpy.models as models
        from pgmpy.factors.discrete import TabularCPD
    except ImportError as e:
        raise ImportError(
            "pgm.Network.to_pgmpy and pgm.from_pgmpy need pgmpy, which is not importable: " + str(e)
        ) from e
    # pgmpy renamed BayesianNetwork to DiscreteBayesianNetwork after 0.1.26.
    model_class = getattr(models, "DiscreteBayesianNetwork", None) or models.BayesianNetwork
    return model_class, TabularCPD


def to_pgmpy(network):
    model_class, TabularCPD = _pgmpy_models()
    model = model_class()
    model.add_nodes_from(network.variables)
    model.add_edges_from(network.edges)
    for name in network.variables:
        parents, _, states, values = network._net.table(name)
        state_names = {name: list(states)}
        for parent in parents:
            state_names[parent] = network.states(parent)
        cpd = TabularCPD(
            variable=name,
            variable_card=len(states),
            values=np.ascontiguousarray(values.T),
            evidence=parents or None,
            evidence_card=[len(network.states(p)) for p in parents] or None,
            state_names=state_names,
        )
        model.add_cpds(cpd)
    model.check_model()
    return model


def from_pgmpy(model):
    from . import Error, Network

    model_class, _ = _pgmpy_models()
    if not isinstance(model, model_class):
        raise TypeError(f"expected a pgmpy {model_class.__name__}, got {type(model).__name__}")
    tables = []
    for node in model.nodes():
        cpd = model.get_cpds(node)
        if cpd is None:
            raise Error(f"the pgmpy model has no table for '{node}'")
        if not hasattr(cpd, "get_values") or not hasattr(cpd, "state_names"):
            raise Error(f"the table of '{node}' is not a discrete table (TabularCPD)")
        variables = list(cpd.variables)
        if variables[0] != node:
            raise Error(f"the table given for '{node}' describes '{variables[0]}'")
        states = [str(s) for s in cpd.state_names[node]]
        parents = [str(p) for p in variables[1:]]
        values = np.asarray(cpd.get_values(), dtype=np.float64).T
        tables.append((str(node), states, parents, np.ascontiguousarray(values)))
    return Network(_core.network_from_tables(tables))
