"""The paper's case study: transfer the ColorBlocksworld plan to Kitchenworld.

    python3 examples/python/case_study.py      (from the repository root)
"""
import catplan

m = catplan.load("examples/colorblocks_to_kitchen/appendix_map.cp")
plan = catplan.Plan.load("examples/colorblocksworld/paper.plan")
t = catplan.transfer(m["ColorToKitchen"], m["CaseStudy"], plan, rename_by_type=True)
for i, step in enumerate(t.steps, 1):
    print(f"{i}. {step.source} -> {step.target}")
print("valid" if t.valid else f"invalid: {t.reason}")
print(f"goal satisfaction: {t.goal.satisfied}/{t.goal.total}")
