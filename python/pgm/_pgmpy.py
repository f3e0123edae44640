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


# Dynamic networks. pgmpy's DynamicBayesianNetwork names a node (X, 0) or (X, 1); it has one set
# of intra-slice edges, for both slices, and makes the node (X, 1) only from an edge into it or
# within its slice. pgm's transition parent "X@-1" is pgmpy's (X, 0) seen from slice 1.


def _dynamic_class():
    try:
        from pgmpy.factors.discrete import TabularCPD
        from pgmpy.models import DynamicBayesianNetwork
    except ImportError as e:
        raise ImportError(
            "pgm.DynamicNetwork.to_pgmpy and pgm.from_pgmpy need pgmpy, which is not importable: " + str(e)
        ) from e
    return DynamicBayesianNetwork, TabularCPD


def dynamic_to_pgmpy(dynamic, state_names=True):
    import json

    from . import Error

    model_class, TabularCPD = _dynamic_class()
    document = json.loads(dynamic._model.to_json())
    states = {v["name"]: v["states"] for v in document["variables"]}
    initial_edges = {tuple(e) for e in document["initial"]["edges"]}
    transition = document["transition"]
    intra = {tuple(e) for e in transition["edges"] if not e[0].endswith("@-1")}
    inter = [(e[0][: -len("@-1")], e[1]) for e in transition["edges"] if e[0].endswith("@-1")]
    if initial_edges != intra:
        differ = sorted(initial_edges ^ intra)
        raise Error(
            "pgmpy's DynamicBayesianNetwork has one set of edges within a slice for both slices, and this "
            "model's first slice and transition differ in "
            + ", ".join(f"{a}->{b}" for a, b in differ)
        )
    in_second_slice = {b for _, b in inter} | {x for edge in intra for x in edge}
    missing = [name for name in states if name not in in_second_slice]
    if missing:
        raise Error(
            "pgmpy's DynamicBayesianNetwork cannot hold "
            + ", ".join(f"'{name}'" for name in missing)
            + " after the first slice: it makes a node of the second slice only from an edge into it or "
            "within the slice, and here none has one"
        )
    model = model_class()
    model.add_nodes_from(list(states))
    model.add_edges_from([((a, 0), (b, 0)) for a, b in sorted(intra)] + [((a, 0), (b, 1)) for a, b in inter])

    def table(entry, slice_of):
        node = (entry["variable"], slice_of)
        parents = [(p[: -len("@-1")], 0) if p.endswith("@-1") else (p, slice_of) for p in entry["parents"]]
        values = np.asarray(entry["values"], dtype=np.float64).T
        names = {node: list(states[node[0]])}
        for parent in parents:
            names[parent] = list(states[parent[0]])
        return TabularCPD(
            variable=node,
            variable_card=len(states[node[0]]),
            values=np.ascontiguousarray(values),
            evidence=parents or None,
            evidence_card=[len(states[p[0]]) for p in parents] or None,
            state_names=names if state_names else {},
        )

    model.add_cpds(*[table(t, 0) for t in document["initial"]["tables"]])
    model.add_cpds(*[table(t, 1) for t in transition["tables"]])
    model.check_model()
    return model


def dynamic_from_pgmpy(model):
    import json

    from . import DynamicNetwork, Error

    def table(node, at):
        cpd = model.get_cpds(node=(node, at))
        if cpd is None:
            raise Error(f"the pgmpy model has no table for ('{node}', {at})")
        variables = list(cpd.variables)
        parents = []
        for name, slice_of in (tuple(v) for v in variables[1:]):
            parents.append(str(name) if slice_of == at else f"{name}@-1")
        values = np.asarray(cpd.get_values(), dtype=np.float64).T
        return {"variable": str(node), "parents": parents, "values": values.tolist()}, cpd

    names = sorted({str(node) for node, _ in (tuple(n) for n in model.nodes())})
    variables, initial, transition = [], [], []
    for name in names:
        entry, cpd = table(name, 0)
        variables.append({"name": name, "states": [str(s) for s in cpd.state_names[(name, 0)]]})
        initial.append(entry)
        transition.append(table(name, 1)[0])

    def edges(tables):
        return [[parent, t["variable"]] for t in tables for parent in t["parents"]]

    document = {
        "format": "pgm-model",
        "version": 1,
        "kind": "dynamic",
        "variables": variables,
        "initial": {"edges": edges(initial), "tables": initial},
        "transition": {"edges": edges(transition), "tables": transition},
    }
    return DynamicNetwork(_core.parse_dynamic_json(json.dumps(document), "the pgmpy model"))
