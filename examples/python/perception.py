"""A state built from a robot's perception output, and the paper's plan transferred on it.

The detector reports each block it sees with a colour and what it rests on. We turn that into
a ColorBlocksworld state, check it is the scene of the paper's case study, and transfer the
paper's plan to the kitchen ontology.

    python3 examples/python/perception.py      (from the repository root)
"""
import catplan

# What the perception stack publishes: one dict per detected object.
detections = [
    {"id": "A", "class": "block", "color": "green", "on": "table", "xyz": [0.10, 0.30, 0.02]},
    {"id": "B", "class": "block", "color": "red", "on": "table", "xyz": [0.20, 0.30, 0.02]},
    {"id": "C", "class": "block", "color": "yellow", "on": "table", "xyz": [0.30, 0.30, 0.02]},
    {"id": "D", "class": "block", "color": "purple", "on": "C", "xyz": [0.30, 0.30, 0.06]},
    {"id": "E", "class": "block", "color": "purple", "on": "D", "xyz": [0.30, 0.30, 0.10]},
    {"id": "F", "class": "block", "color": "blue", "on": "table", "xyz": [0.40, 0.30, 0.02]},
]
gripper_is_empty = True


def blocksworld_state(schema, detections, gripper_is_empty):
    """The ColorBlocksworld state of a scene: blocks, what is on what, and the gripper."""
    supports = {d["on"] for d in detections}
    blocks = [{"_name": d["id"], "hasColor": d["color"], "isOnTable": d["on"] == "table",
               "isClear": d["id"] not in supports} for d in detections]
    on = [{"on_l": d["id"], "on_r": d["on"]} for d in detections if d["on"] != "table"]
    # The hand is empty when the gripper holds the block an Empty marks; that marker block's
    # colour and position are unknowns (attribute variables), as in the paper's Table 1.
    marker = len(blocks)
    blocks.append({"hasColor": catplan.Var("Color", 0), "isClear": catplan.Var("Clear", 0),
                   "isOnTable": catplan.Var("OnTable", 0)})
    data = {"Block": blocks, "On": on, "Gripper": [{"_name": "gripper", "isHolding": marker}],
            "Color": [{}], "Clear": [{}], "OnTable": [{}]}
    if gripper_is_empty:
        data["Empty"] = [{"_name": "empty", "isEmpty": marker}]
    return catplan.State.from_dict(schema, data, name="Perceived")


m = catplan.load("examples/colorblocks_to_kitchen/appendix_map.cp")
scene = blocksworld_state(m["ColorBlocksworld"], detections, gripper_is_empty)
print(scene)
print("the paper's initial state:", catplan.is_isomorphic(scene, m["Initial"]))

problem = catplan.Problem(m["Blocksworld"], scene, m["Goal"], name="Perceived")
plan = catplan.Plan.load("examples/colorblocksworld/paper.plan")
t = catplan.transfer(m["ColorToKitchen"], problem, plan, rename_by_type=True)
print("kitchen plan:", "; ".join(str(s.target) for s in t.steps))
print("valid" if t.valid else f"invalid: {t.reason}", f"({t.goal.satisfied}/{t.goal.total})")
