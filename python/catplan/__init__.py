"""catplan: categorical task planning and plan transfer between robot planning domains.

A planning domain is a schema, a state an attributed C-set on it, an action a DPO rewrite rule
Pre <- Keep -> Eff, and an ontology map F : D' -> D carries states, actions and plans from one
domain to another (Aguinaldo, Patterson, Regli, *Functorial plan transfer*).

    import catplan
    m = catplan.load("examples/colorblocks_to_kitchen/appendix_map.cp")
    t = catplan.transfer(m["ColorToKitchen"], m["CaseStudy"],
                         catplan.Plan.load("examples/colorblocksworld/paper.plan"))
    print(t.valid, [str(s.target) for s in t.steps])

Errors in input raise CatplanError, whose ``diagnostics`` are located (file, line, column,
message). Long calls (plan search, homomorphism search, transfer, loading) release the GIL, and
Ctrl-C interrupts the searches. See docs/python.md.
"""

from __future__ import annotations

from typing import Any, Dict

from ._catplan import (
    CatplanError,
    Claim,
    Diagnostic,
    Domain,
    Fault,
    GoalSatisfaction,
    Hypothesis,
    IpcValidation,
    Map,
    Module,
    Morphism,
    PddlTask,
    PddlTransfer,
    PddlTransferStep,
    Plan,
    Problem,
    Replan,
    Rule,
    Schema,
    SearchResult,
    State,
    Step,
    Transfer,
    TransferStep,
    Validation,
    Var,
    Verdict,
    compose,
    count_homs,
    export_pddl,
    export_pddl_problem,
    hom,
    homs,
    is_isomorphic,
    load,
    load_pddl,
    loads,
    loads_pddl,
    migrate,
    migrate_domain,
    parse_ipc_plan,
    plan,
    sigma,
    transfer,
    transfer_pddl,
    validate,
)

__version__ = "0.1.0"

__all__ = [
    "CatplanError", "Claim", "Diagnostic", "Domain", "Fault", "GoalSatisfaction", "Hypothesis",
    "IpcValidation", "Map", "Module", "Morphism", "PddlTask", "PddlTransfer", "PddlTransferStep",
    "Plan", "Problem", "Replan", "Rule", "Schema",
    "SearchResult", "State", "Step", "Transfer", "TransferStep", "Validation", "Var", "Verdict",
    "compose", "count_homs", "export_pddl", "export_pddl_problem", "hom", "homs",
    "is_isomorphic", "load", "load_pddl", "loads", "loads_pddl", "migrate", "migrate_domain",
    "parse_ipc_plan", "plan", "sigma", "to_tables", "transfer", "transfer_pddl",
    "validate",
]


def _column(values: list, kind: str, np: Any) -> Any:
    # A typed array when every cell is a concrete value of the column's kind, else objects
    # (unknowns stay Var, unset cells None).
    if kind == "hom":
        return np.array([-1 if v is None else v for v in values], dtype=np.int64)
    types = {"Bool": bool, "Int": int, "Float": float}
    t = types.get(kind)
    if t is not None and all(type(v) is t or (t is float and type(v) is int) for v in values):
        return np.array(values, dtype={bool: np.bool_, int: np.int64, float: np.float64}[t])
    return np.array(values, dtype=object)


def to_tables(state: State) -> Dict[str, Dict[str, Any]]:
    """The state as one table per object: {object: {column: column values}}.

    Columns are "_name", then each hom, then each attribute, one entry per part. With numpy
    installed each column is a numpy array (homs as int64 part indexes with -1 for unset,
    Bool/Int/Float attributes typed when every cell is concrete, other columns of dtype
    object), so ``pandas.DataFrame(to_tables(x)["Block"])`` is a table; without numpy, lists.
    """
    try:
        import numpy as np
    except ImportError:  # numpy is optional
        np = None
    schema = state.schema
    kinds = dict(schema.attr_types)
    attr_kind = {name: kinds[t] for name, _, t in schema.attrs}
    homs_ = {name for name, _, _ in schema.homs}
    out: Dict[str, Dict[str, Any]] = {}
    for ob in schema.obs:
        cols = state.columns(ob)
        if np is None:
            out[ob] = cols
            continue
        table = {}
        for name, values in cols.items():
            if name == "_name":
                table[name] = np.array(values, dtype=object)
            elif name in homs_:
                table[name] = _column(values, "hom", np)
            else:
                table[name] = _column(values, attr_kind[name], np)
        out[ob] = table
    return out


State.to_tables = to_tables  # type: ignore[attr-defined]
