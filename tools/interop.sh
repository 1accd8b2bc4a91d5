#!/usr/bin/env bash
# `make interop`: catplan's PDDL export checked against the standard tools (Fast Downward, VAL).
# Not part of `make test`: the peers are not part of the product. For every example domain and
# problem (and each map's migrated target), export, solve with Fast Downward lama-first, validate
# FD's plan with VAL and with `catplan validate` on the exported files, and read it back as a plan
# of the catplan problem (`pddl export --from-ipc`, which checks it there); then carry each example
# plan to the export (`pddl export --plan`) and validate it with VAL, the case study's transferred
# target plan included. Prints a table; exits 1 on any disagreement, 0 when every check agrees.
#
#   make interop                         # PEERS defaults to /work/shared/peers or ../shared/peers
#   PEERS=/path/to/peers tools/interop.sh [CATPLAN]
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
catplan=${1:-$root/build/release/src/catplan/cli/catplan}
if [ -z "${PEERS:-}" ]; then
    for p in /work/shared/peers "$root/../shared/peers" "$root/../../shared/peers"; do
        [ -d "$p/bin" ] && PEERS=$p && break
    done
fi
if [ -z "${PEERS:-}" ] || [ ! -x "$PEERS/bin/fast-downward" ] || [ ! -x "$PEERS/bin/validate" ]; then
    echo "interop: skipped: no peers (Fast Downward and VAL) in \$PEERS, /work/shared/peers or ../shared/peers"
    exit 0
fi
if [ ! -x "$catplan" ]; then
    echo "interop: no catplan at $catplan (build it: cmake --build --preset release --target catplan)" >&2
    exit 2
fi
# Absolute: Fast Downward runs in the work directory (it writes sas_plan where it runs).
PEERS=$(cd "$PEERS" && pwd)
fd=$PEERS/bin/fast-downward
val=$PEERS/bin/validate
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$root" || exit 2

# name | file | export options | a catplan plan of the problem (after --map, the source's plan:
# a migrated rule keeps its name and its parameters' names), `transfer` for the case study's
# transferred target plan, or -
cases=(
"casestudy|examples/colorblocksworld/colorblocksworld.cp|--problem CaseStudy|examples/colorblocksworld/paper.plan"
"slides|examples/colorblocksworld/slides.cp|--problem SlidesCaseStudy|examples/colorblocksworld/paper.plan"
"hanoi|examples/hanoi/hanoi.cp|--problem ThreeDiscs|examples/hanoi/hanoi.plan"
"sandwich|examples/sandwich_kitchen/sandwich_kitchen.cp|--problem MakeSandwich|examples/sandwich_kitchen/sandwich.plan"
"lights|tests/pddl/lights.cp|--problem LightsProblem|-"
"lights>rooms|tests/pddl/lights.cp|--problem LightsProblem --map LightsToRooms|-"
"casestudy>kitchen|examples/colorblocks_to_kitchen/appendix_map.cp|--problem CaseStudy --map ColorToKitchen|transfer"
"slides>kitchen|examples/colorblocks_to_kitchen/slides_map.cp|--problem SlidesCaseStudy --map ColorToKitchen|examples/colorblocksworld/paper.plan"
"casestudy>swapped|examples/colorblocks_to_kitchen/swapped_map.cp|--problem CaseStudy --map SwappedToKitchen|examples/colorblocksworld/paper.plan"
"casestudy>plain|examples/colorblocks_to_blocks/forget_colors.cp|--problem CaseStudy --map ForgetColors|examples/colorblocksworld/paper.plan"
"hanoi>blocks|examples/hanoi_to_blocks/hanoi_to_blocks.cp|--problem ThreeDiscs --map HanoiToBlocks|examples/hanoi/hanoi.plan"
"sandwich>color|examples/kitchen_to_colorblocks/kitchen_to_color.cp|--problem MakeSandwich --map KitchenToColor|examples/sandwich_kitchen/sandwich.plan"
"casestudy>warehouse|examples/kitchen_to_warehouse/kitchen_to_warehouse.cp|--problem CaseStudy --map ColorToWarehouse|examples/colorblocksworld/paper.plan"
"roads|tests/cli/data/roads.cp|--problem ToD|tests/cli/data/roads_cheapest.plan"
)

bad=0
# fd-plan: the steps of FD's plan, reach-goal included when the goal is a pattern; VAL and
# catplan: FD's plan on the export; read-back: FD's plan as a plan of the catplan problem; the
# second VAL: the example's (or transferred) plan carried to the export.
printf '%-20s %-7s %-9s %-6s %-9s %-9s %-6s %s\n' case export fd-plan VAL catplan read-back VAL notes
for c in "${cases[@]}"; do
    IFS='|' read -r name file opts plan <<<"$c"
    d=$work/$name.domain.pddl p=$work/$name.problem.pddl
    # shellcheck disable=SC2086
    if ! "$catplan" pddl export "$file" $opts -o "$d" --problem-output "$p" 2>"$work/err"; then
        printf '%-20s %-7s %s\n' "$name" FAIL "$(grep -v '^catplan: note' "$work/err" | head -1)"
        bad=1
        continue
    fi
    (cd "$work" && rm -f sas_plan && "$fd" --alias lama-first --overall-time-limit 60s "$d" "$p" >"$work/fd.log" 2>&1)
    if [ ! -s "$work/sas_plan" ]; then
        printf '%-20s %-7s %-9s\n' "$name" ok none
        bad=1
        continue
    fi
    steps=$(grep -c '^(' "$work/sas_plan")
    v1=$("$val" "$d" "$p" "$work/sas_plan" >/dev/null 2>&1 && echo valid || echo INVALID)
    v2=$("$catplan" validate "$d" "$p" "$work/sas_plan" >/dev/null 2>&1 && echo valid || echo INVALID)
    # shellcheck disable=SC2086
    v3=$("$catplan" pddl export "$file" $opts --from-ipc "$work/sas_plan" 2>/dev/null >"$work/back.plan" && echo valid || echo INVALID)
    v4=-
    note=""
    if [ "$plan" = transfer ]; then
        src=${opts%% --map*}; src=${src#--problem }
        map=${opts##*--map }
        "$catplan" transfer "$file" --map "$map" --problem "$src" --plan examples/colorblocksworld/paper.plan --format json --no-timing 2>/dev/null |
            python3 -c 'import json,sys; print("\n".join(json.load(sys.stdin)["target_plan"]))' >"$work/given.plan"
        plan=$work/given.plan
        note="transferred paper plan"
    fi
    if [ "$plan" != - ]; then
        # shellcheck disable=SC2086
        if "$catplan" pddl export "$file" $opts --plan "$plan" -o "$work/given.ipc" 2>/dev/null; then
            v4=$("$val" "$d" "$p" "$work/given.ipc" >/dev/null 2>&1 && echo valid || echo INVALID)
            note="${note:-example plan}: $(grep -c '^(' "$work/given.ipc") IPC steps"
        else
            v4=FAIL
        fi
    fi
    printf '%-20s %-7s %-9s %-6s %-9s %-9s %-6s %s\n' "$name" ok "$steps" "$v1" "$v2" "$v3" "$v4" "$note"
    for v in "$v1" "$v2" "$v3" "$v4"; do
        case $v in valid | -) ;; *) bad=1 ;; esac
    done
done
# Action costs read from a problem's functions: catplan's A* on the .cp problem and FD's
# astar(lmcut()) on its export find plans of one least cost, and VAL values FD's plan at it.
for c in "tests/cli/data/roads.cp|ToD"; do
    IFS='|' read -r file problem <<<"$c"
    d=$work/costs.domain.pddl p=$work/costs.problem.pddl
    "$catplan" pddl export "$file" --problem "$problem" -o "$d" --problem-output "$p" 2>/dev/null
    ours=$("$catplan" plan "$file" --problem "$problem" --search astar --no-timing | sed -n 's/^# cost = //p')
    (cd "$work" && rm -f sas_plan && "$fd" --overall-time-limit 60s "$d" "$p" --search "astar(lmcut())" >"$work/fd.log" 2>&1)
    theirs=$(sed -n 's/^; cost = \([0-9]*\).*/\1/p' "$work/sas_plan" 2>/dev/null)
    val_value=$("$val" "$d" "$p" "$work/sas_plan" 2>/dev/null | sed -n 's/^Final value: *\([0-9]*\).*/\1/p')
    printf 'least cost of %s %s: catplan astar %s, FD astar(lmcut()) %s, VAL %s\n' "$file" "$problem" \
        "${ours:-none}" "${theirs:-none}" "${val_value:-none}"
    if [ -z "$ours" ] || [ "$ours" != "$theirs" ] || [ "$ours" != "$val_value" ]; then
        bad=1
    fi
done
# Costs carried through a transfer between PDDL domains (a map's functions section): VAL values
# the transferred plan on the written target problem at the cost catplan reports, and FD's
# astar(lmcut()) finds that problem's least cost.
# ToCharters: each drive repaired by an A* that sums the carried fares (not the one-step charter).
for c in "tests/pddl/roads_to_transit.cp|ToTransit|tests/pddl/roads-domain.pddl|tests/pddl/transit-domain.pddl|tests/pddl/roads-p01.pddl|tests/pddl/roads-p01.plan" \
    "tests/pddl/roads_to_transit.cp|ToCharters|tests/pddl/roads-domain.pddl|tests/pddl/charters-domain.pddl|tests/pddl/roads-p01.pddl|tests/pddl/roads-p01.plan"; do
    IFS='|' read -r file map source_domain target_domain problem plan <<<"$c"
    tp=$work/transfer.plan tq=$work/transfer.problem.pddl
    ours=$("$catplan" transfer "$file" --map "$map" --problem "$problem" --plan "$plan" -o "$tp" \
        --problem-output "$tq" --no-timing 2>/dev/null | sed -n 's/^target plan cost: \([0-9]*\).*/\1/p')
    src=$("$val" "$source_domain" "$problem" "$plan" 2>/dev/null | sed -n 's/^Final value: *\([0-9]*\).*/\1/p')
    val_value=$("$val" "$target_domain" "$tq" "$tp" 2>/dev/null | sed -n 's/^Final value: *\([0-9]*\).*/\1/p')
    (cd "$work" && rm -f sas_plan && "$fd" --overall-time-limit 60s "$root/$target_domain" "$tq" --search "astar(lmcut())" >"$work/fd.log" 2>&1)
    theirs=$(sed -n 's/^; cost = \([0-9]*\).*/\1/p' "$work/sas_plan" 2>/dev/null)
    printf 'transfer %s along %s: source plan VAL %s; target plan catplan %s, VAL %s; FD astar(lmcut()) on the target problem %s\n' \
        "$plan" "$map" "${src:-none}" "${ours:-none}" "${val_value:-none}" "${theirs:-none}"
    if [ -z "$ours" ] || [ "$ours" != "$val_value" ] || [ "$ours" != "$src" ] || [ "$ours" != "$theirs" ]; then
        bad=1
    fi
done
if [ $bad -ne 0 ]; then
    echo "interop: some check disagrees"
    exit 1
fi
echo "interop: every export solved by Fast Downward, every plan accepted by VAL and by catplan"
