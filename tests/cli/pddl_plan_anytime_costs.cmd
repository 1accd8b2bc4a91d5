plan tests/pddl/roads-domain.pddl tests/pddl/roads-p01.pddl --anytime --no-timing
