# A PDDL domain catplan does not read, imported: `check` names what it does not support and
# exits 3.
@import "unsupported-domain.pddl"
