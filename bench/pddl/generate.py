#!/usr/bin/env python3
"""Seeded problem generators for the benchmark domains in bench/pddl/domains (IPC style).

    generate.py OUT_DIR            writes OUT_DIR/<domain>/p<NN>.pddl for every domain and size
    generate.py OUT_DIR --list     prints the problems it would write

Each generator takes a size tuple and a seed and returns the problem text; the sizes below go from
small to medium (the IPC's first problems). Same seed, same problem.
"""
import itertools
import pathlib
import random
import sys


def problem(domain, name, objects, init, goal, metric=False):
    objs = "\n    ".join(f"{' '.join(names)} - {t}" for t, names in objects if names)
    init_s = "\n    ".join(init)
    goal_s = "\n      ".join(goal)
    metric_s = "\n  (:metric minimize (total-cost))" if metric else ""
    return (f"(define (problem {name}) (:domain {domain})\n  (:objects\n    {objs})\n"
            f"  (:init\n    {init_s})\n  (:goal (and\n      {goal_s})){metric_s})\n")


def towers(blocks, rng):
    order = blocks[:]
    rng.shuffle(order)
    result, current = [], []
    for b in order:
        current.append(b)
        if rng.random() < 0.3:
            result.append(current)
            current = []
    if current:
        result.append(current)
    return result


def blocksworld(size, rng, name):
    (n,) = size
    blocks = [f"b{i}" for i in range(1, n + 1)]
    init = ["(handempty)"]
    for t in towers(blocks, rng):
        init.append(f"(ontable {t[0]})")
        init += [f"(on {a} {b})" for b, a in zip(t, t[1:])]
        init.append(f"(clear {t[-1]})")
    goal = []
    for t in towers(blocks, rng):
        goal += [f"(on {a} {b})" for b, a in zip(t, t[1:])]
    if not goal:
        goal = [f"(on {blocks[0]} {blocks[1]})"]
    return problem("blocksworld", name, [("block", blocks)], init, goal)


def gripper(size, rng, name):
    (n,) = size
    balls = [f"ball{i}" for i in range(1, n + 1)]
    init = ["(at-robby rooma)", "(free left)", "(free right)"] + [f"(at {b} rooma)" for b in balls]
    return problem("gripper", name,
                   [("room", ["rooma", "roomb"]), ("ball", balls), ("gripper", ["left", "right"])],
                   init, [f"(at {b} roomb)" for b in balls])


def logistics(size, rng, name):
    cities, per_city, packages, planes = size
    cs = [f"city{i}" for i in range(1, cities + 1)]
    locs = {c: [f"{c}-loc{j}" for j in range(1, per_city + 1)] for c in cs}
    airports = [locs[c][0] for c in cs]
    others = [l for c in cs for l in locs[c][1:]]
    trucks = [f"truck{i}" for i in range(1, cities + 1)]
    planes_ = [f"plane{i}" for i in range(1, planes + 1)]
    pkgs = [f"pkg{i}" for i in range(1, packages + 1)]
    every = [l for c in cs for l in locs[c]]
    init = [f"(in-city {l} {c})" for c in cs for l in locs[c]]
    init += [f"(at {t} {rng.choice(locs[c])})" for t, c in zip(trucks, cs)]
    init += [f"(at {p} {rng.choice(airports)})" for p in planes_]
    start = {p: rng.choice(every) for p in pkgs}
    init += [f"(at {p} {start[p]})" for p in pkgs]
    goal = [f"(at {p} {rng.choice([l for l in every if l != start[p]])})" for p in pkgs]
    return problem("logistics", name,
                   [("truck", trucks), ("airplane", planes_), ("package", pkgs),
                    ("airport", airports), ("location", others), ("city", cs)], init, goal)


def miconic(size, rng, name):
    floors, passengers = size
    fs = [f"f{i}" for i in range(floors)]
    ps = [f"p{i}" for i in range(passengers)]
    init = [f"(above {fs[i]} {fs[j]})" for i in range(floors) for j in range(i + 1, floors)]
    init.append(f"(lift-at {fs[0]})")
    for p in ps:
        o, d = rng.sample(fs, 2)
        init += [f"(origin {p} {o})", f"(destin {p} {d})"]
    return problem("miconic", name, [("passenger", ps), ("floor", fs)], init,
                   [f"(served {p})" for p in ps])


def visitall(size, rng, name):
    (n,) = size
    cells = [f"cell-{x}-{y}" for x in range(n) for y in range(n)]
    init = [f"(at-robot cell-0-0)", "(visited cell-0-0)"]
    for x, y in itertools.product(range(n), repeat=2):
        for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1)):
            if 0 <= x + dx < n and 0 <= y + dy < n:
                init.append(f"(connected cell-{x}-{y} cell-{x + dx}-{y + dy})")
    return problem("visitall", name, [("place", cells)], init, [f"(visited {c})" for c in cells])


def satellite(size, rng, name):
    sats, per_sat, modes, dirs, goals = size
    ss = [f"sat{i}" for i in range(sats)]
    ms = [f"mode{i}" for i in range(modes)]
    ds = [f"dir{i}" for i in range(dirs)]
    ins, init = [], []
    for s in ss:
        init += [f"(power_avail {s})", f"(pointing {s} {rng.choice(ds)})"]
        for k in range(per_sat):
            i = f"{s}-ins{k}"
            ins.append(i)
            init += [f"(on_board {i} {s})", f"(calibration_target {i} {rng.choice(ds)})"]
            init += [f"(supports {i} {m})" for m in rng.sample(ms, rng.randint(1, len(ms)))]
    supported = {m for line in init if line.startswith("(supports") for m in [line.split()[2][:-1]]}
    pairs = [(d, m) for d in ds for m in ms if m in supported]
    goal = [f"(have_image {d} {m})" for d, m in rng.sample(pairs, min(goals, len(pairs)))]
    goal.append(f"(pointing {ss[0]} {rng.choice(ds)})")
    return problem("satellite", name,
                   [("satellite", ss), ("instrument", ins), ("mode", ms), ("direction", ds)],
                   init, goal)


def rovers(size, rng, name):
    nr, nw, no, goals = size
    rs = [f"rover{i}" for i in range(nr)]
    ws = [f"wp{i}" for i in range(nw)]
    os_ = [f"obj{i}" for i in range(no)]
    stores = [f"{r}-store" for r in rs]
    cams = [f"{r}-cam" for r in rs]
    modes = ["colour", "high_res", "low_res"]
    init = ["(at_lander general wp0)", "(channel_free general)"]
    for a, b in itertools.permutations(ws, 2):
        if rng.random() < 0.6 or abs(ws.index(a) - ws.index(b)) == 1:
            init.append(f"(visible {a} {b})")
    visible = {tuple(l[9:-1].split()) for l in init if l.startswith("(visible ")}
    for r, st, c in zip(rs, stores, cams):
        init += [f"(at {r} {rng.choice(ws)})", f"(available {r})", f"(store_of {st} {r})",
                 f"(empty {st})", "(equipped_for_soil_analysis " + r + ")",
                 f"(equipped_for_rock_analysis {r})", f"(equipped_for_imaging {r})",
                 f"(on_board {c} {r})", f"(calibration_target {c} {rng.choice(os_)})"]
        init += [f"(supports {c} {m})" for m in modes]
        init += [f"(can_traverse {r} {a} {b})" for a, b in sorted(visible)]
    soil = rng.sample(ws, max(1, nw // 2))
    rock = rng.sample(ws, max(1, nw // 2))
    init += [f"(at_soil_sample {w})" for w in soil] + [f"(at_rock_sample {w})" for w in rock]
    for o in os_:
        init += [f"(visible_from {o} {w})" for w in rng.sample(ws, max(1, nw // 3))]
    candidates = ([f"(communicated_soil_data {w})" for w in soil] +
                  [f"(communicated_rock_data {w})" for w in rock] +
                  [f"(communicated_image_data {o} {m})" for o in os_ for m in modes])
    return problem("rovers", name,
                   [("rover", rs), ("waypoint", ws), ("store", stores), ("camera", cams),
                    ("mode", modes), ("lander", ["general"]), ("objective", os_)],
                   init, rng.sample(candidates, min(goals, len(candidates))))


def childsnack(size, rng, name):
    children, trays, tables, allergic = size
    cs = [f"child{i}" for i in range(children)]
    bread = [f"bread{i}" for i in range(children)]
    content = [f"content{i}" for i in range(children)]
    sandwiches = [f"sandw{i}" for i in range(children)]
    ts = [f"tray{i}" for i in range(trays)]
    tbls = [f"table{i}" for i in range(tables)]
    init = [f"(at {t} kitchen)" for t in ts]
    init += [f"(at_kitchen_bread {b})" for b in bread]
    init += [f"(at_kitchen_content {c})" for c in content]
    init += [f"(no_gluten_bread {b})" for b in bread[:allergic]]
    init += [f"(no_gluten_content {c})" for c in content[:allergic]]
    init += [f"(notexist {s})" for s in sandwiches]
    for i, c in enumerate(cs):
        init.append(f"(allergic_gluten {c})" if i < allergic else f"(not_allergic_gluten {c})")
        init.append(f"(waiting {c} {rng.choice(tbls)})")
    return problem("childsnack", name,
                   [("child", cs), ("bread-portion", bread), ("content-portion", content),
                    ("sandwich", sandwiches), ("tray", ts), ("place", tbls)],
                   init, [f"(served {c})" for c in cs])


def depots(size, rng, name):
    nd, ndist, ntrucks, ncrates = size
    places = [f"depot{i}" for i in range(nd)] + [f"distributor{i}" for i in range(ndist)]
    pallets = [f"pallet{i}" for i in range(len(places))]
    hoists = [f"hoist{i}" for i in range(len(places))]
    trucks = [f"truck{i}" for i in range(ntrucks)]
    crates = [f"crate{i}" for i in range(ncrates)]
    init = []
    for p, pal, h in zip(places, pallets, hoists):
        init += [f"(at {pal} {p})", f"(at {h} {p})", f"(available {h})"]
    init += [f"(at {t} {rng.choice(places)})" for t in trucks]
    top = {pal: pal for pal in pallets}
    where = {pal: p for pal, p in zip(pallets, places)}
    for c in crates:
        pal = rng.choice(pallets)
        init += [f"(at {c} {where[pal]})", f"(on {c} {top[pal]})"]
        top[pal] = c
    init += [f"(clear {t})" for t in top.values()]
    goal = []
    surfaces = pallets[:]
    for c in rng.sample(crates, max(1, ncrates * 2 // 3)):
        s = rng.choice(surfaces)
        goal.append(f"(on {c} {s})")
        surfaces.remove(s)
        surfaces.append(c)
    return problem("depots", name,
                   [("depot", places[:nd]), ("distributor", places[nd:]), ("truck", trucks),
                    ("pallet", pallets), ("hoist", hoists), ("crate", crates)], init, goal)


def pipesworld(size, rng, name):
    areas, batches_per_pipe, extra, goals = size
    ars = [f"a{i}" for i in range(areas)]
    pipes = [f"s{i}{i + 1}" for i in range(areas - 1)]
    products = ["gasoleo", "rat-a", "oca1"]
    batches, init, slots = [], [], []
    for i, p in enumerate(pipes):
        init.append(f"(connect {ars[i]} {ars[i + 1]} {p})")
        b = f"b{len(batches)}"
        batches.append(b)
        init.append(f"(in-pipe {b} {p})")
    for a in ars:
        for k in range(extra + batches_per_pipe):
            s = f"{a}-slot{k}"
            slots.append(s)
            init.append(f"(tank-slot {s} {a})")
    free = slots[:]
    rng.shuffle(free)
    for _ in range(extra * areas // 2 + 1):
        b = f"b{len(batches)}"
        batches.append(b)
        s = free.pop()
        a = s.split("-")[0]
        init += [f"(on {b} {a})", f"(stored {b} {s})", f"(occupied {s})"]
    for b in batches:
        init.append(f"(is-product {b} {rng.choice(products)})")
    for x, y in itertools.product(products, repeat=2):
        if (x, y) not in (("rat-a", "oca1"), ("oca1", "rat-a")):
            init.append(f"(may-interface {x} {y})")
    goal = [f"(on {b} {rng.choice(ars)})" for b in rng.sample(batches, min(goals, len(batches)))]
    return problem("pipesworld", name,
                   [("area", ars), ("pipe", pipes), ("batch", batches), ("product", products),
                    ("slot", slots)], init, goal)


def mystery(size, rng, name):
    nl, nv, nc, fuel = size
    ls = [f"loc{i}" for i in range(nl)]
    vs = [f"veh{i}" for i in range(nv)]
    cs = [f"cargo{i}" for i in range(nc)]
    fs = [f"f{i}" for i in range(fuel + 1)]
    sps = ["s0", "s1", "s2"]
    init = [f"(fuel-neighbor {fs[i]} {fs[i + 1]})" for i in range(fuel)]
    init += [f"(space-neighbor {sps[i]} {sps[i + 1]})" for i in range(2)]
    order = ls[:]
    rng.shuffle(order)
    edges = set()
    for a, b in zip(order, order[1:]):
        edges |= {(a, b), (b, a)}
    for a, b in itertools.permutations(ls, 2):
        if rng.random() < 0.25:
            edges |= {(a, b), (b, a)}
    init += [f"(conn {a} {b})" for a, b in sorted(edges)]
    init += [f"(has-fuel {l} {fs[rng.randint(1, fuel)]})" for l in ls]
    init += [f"(at {v} {rng.choice(ls)})" for v in vs] + [f"(has-space {v} s2)" for v in vs]
    start = {c: rng.choice(ls) for c in cs}
    init += [f"(cargo-at {c} {start[c]})" for c in cs]
    goal = [f"(cargo-at {c} {rng.choice([l for l in ls if l != start[c]])})" for c in cs]
    return problem("mystery", name,
                   [("location", ls), ("vehicle", vs), ("cargo", cs), ("fuel", fs),
                    ("space", sps)], init, goal)


def freecell(size, rng, name):
    nsuits, nvalues, ncols, ncells = size
    suits = ["hearts", "spades", "diamonds", "clubs"][:nsuits]
    red = {"hearts", "diamonds"}
    nums = [f"n{i}" for i in range(max(nvalues, ncols, ncells) + 1)]
    cards = [f"{s[0]}{v}" for s in suits for v in range(1, nvalues + 1)]
    homes = [f"{s[0]}0" for s in suits]
    init = [f"(successor {nums[i + 1]} {nums[i]})" for i in range(len(nums) - 1)]
    for s in suits:
        init += [f"(home {s[0]}0)", f"(suit {s[0]}0 {s})", f"(value {s[0]}0 n0)"]
        for v in range(1, nvalues + 1):
            init += [f"(suit {s[0]}{v} {s})", f"(value {s[0]}{v} {nums[v]})"]
    for s, t in itertools.product(suits, repeat=2):
        if (s in red) != (t in red):
            init += [f"(canstack {s[0]}{v} {t[0]}{v + 1})" for v in range(1, nvalues)]
    deck = cards[:]
    rng.shuffle(deck)
    columns = [deck[i::ncols] for i in range(ncols)]
    for col in columns:
        if not col:
            continue
        init.append(f"(bottomcol {col[0]})")
        init += [f"(on {a} {b})" for b, a in zip(col, col[1:])]
        init.append(f"(clear {col[-1]})")
    init += [f"(cellspace {nums[ncells]})", "(colspace n0)"]
    return problem("freecell", name, [("card", cards + homes), ("num", nums), ("suit", suits)],
                   init, [f"(home {s[0]}{nvalues})" for s in suits])


# Sizes per domain, smallest first: the first few problems of an IPC-style series.
def transport(size, rng, name):
    """A ring of locations with random chords, lengths 1 to 20 (both ways alike), trucks and
    packages at random places, each package bound elsewhere."""
    locations, trucks, packages = size
    locs = [f"l{i}" for i in range(1, locations + 1)]
    edges = {(i, (i + 1) % locations) for i in range(locations)}
    while len(edges) < 2 * locations:
        a, b = rng.sample(range(locations), 2)
        if (b, a) not in edges:
            edges.add((a, b))
    init = ["(= (total-cost) 0)"]
    for a, b in sorted(edges):
        length = rng.randint(1, 20)
        for x, y in ((a, b), (b, a)):
            init += [f"(road {locs[x]} {locs[y]})", f"(= (road-length {locs[x]} {locs[y]}) {length})"]
    ts = [f"t{i}" for i in range(1, trucks + 1)]
    ps = [f"p{i}" for i in range(1, packages + 1)]
    init += [f"(at {t} {rng.choice(locs)})" for t in ts]
    goal = []
    for p in ps:
        start, end = rng.sample(locs, 2)
        init.append(f"(at {p} {start})")
        goal.append(f"(at {p} {end})")
    return problem("transport", name, [("location", locs), ("truck", ts), ("package", ps)], init,
                   goal, metric=True)


# Domains whose actions cost what the problem says: their own series (planner_vs_fd.py costs).
COST_SIZES = {
    "transport": [(6, 1, 2), (6, 2, 3), (8, 2, 3), (8, 2, 4), (10, 2, 4), (10, 3, 5)],
}

SIZES = {
    "blocksworld": [(n,) for n in (6, 8, 10, 12)],
    "gripper": [(n,) for n in (4, 6, 8, 10)],
    "logistics": [(2, 2, 2, 1), (2, 3, 3, 1), (3, 2, 4, 1), (3, 3, 5, 2)],
    "miconic": [(3, 2), (4, 3), (6, 4), (8, 6)],
    "visitall": [(n,) for n in (3, 4, 5, 6)],
    "satellite": [(1, 1, 2, 3, 2), (1, 2, 2, 4, 3), (2, 2, 3, 5, 4), (2, 2, 3, 6, 6)],
    "rovers": [(1, 4, 2, 2), (1, 5, 2, 3), (2, 5, 3, 4), (2, 6, 3, 5)],
    "childsnack": [(3, 1, 2, 1), (4, 2, 2, 2), (5, 2, 3, 2), (6, 2, 3, 3)],
    "depots": [(1, 1, 1, 2), (1, 1, 2, 3), (1, 2, 2, 4), (2, 2, 2, 5)],
    "pipesworld": [(3, 1, 1, 2), (3, 1, 2, 3), (4, 1, 1, 3), (4, 1, 2, 4)],
    "mystery": [(4, 1, 2, 3), (5, 2, 2, 3), (6, 2, 3, 4), (6, 2, 4, 4)],
    "freecell": [(2, 2, 2, 2), (2, 3, 3, 2), (2, 4, 3, 2), (3, 3, 3, 2)],
}

GENERATORS = {name: globals()[name] for name in [*SIZES, *COST_SIZES]}


def main():
    out = pathlib.Path(sys.argv[1])
    only_list = "--list" in sys.argv
    for domain, sizes in SIZES.items():
        for i, size in enumerate(sizes, 1):
            name = f"{domain}-p{i:02d}"
            path = out / domain / f"p{i:02d}.pddl"
            if only_list:
                print(path)
                continue
            rng = random.Random(1000 * i + len(domain))
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(GENERATORS[domain](size, rng, name))


if __name__ == "__main__":
    main()
