"""The tables of docs/validation.md's "The reference and every technique against truth", from
the runs scripts/validate-against-truth.sh made.
Usage: validation_table.py OUT TECHNIQUE...   (Markdown on stdout)

Figures are over the reference's skin mask. "Visible" against truth counts the pixels whose
FLIP error is above both the visibility threshold and the truth's noise floor there
(docs/validation.md); against the reference, above the threshold.
"""
import json
import math
import sys

OUT, TECHNIQUES = sys.argv[1], sys.argv[2:]
SCENES = {"head": "The built-in head", "scan": "The scan (LeePerrySmith.glb, life size)"}


def load(path):
    with open(path) as f:
        return json.load(f)


def number(value, digits):
    return f"{value:.{digits}f}" if isinstance(value, (int, float)) else str(value)


def figures(m, visible=True):
    cells = [number(m["psnr_db"], 2), number(m["ssim"], 3), number(m["flip"], 3)]
    return cells + [f"{m['visible_pct']:.1f}%" if visible else "-"]


def quality(q):
    """result.json's figures against skinsim's own reference."""
    return [number(q["psnr_skin"], 2), number(q["ssim_skin"], 3), number(q["flip_skin"], 3),
            f"{q['visible_skin_pct']:.1f}%"]


def row(name, against_truth, against_reference):
    print("| " + " | ".join([name] + against_truth + against_reference) + " |")


for scene, title in SCENES.items():
    six = load(f"{OUT}/{scene}/run_six_gaussian_mobile/result.json")["truth"]
    dipole = load(f"{OUT}/{scene}/run_dipole_mobile/result.json")["truth"]
    made = {p: load(f"{OUT}/{scene}/truth_{p}/truth.json") for p in ("six_gaussian", "dipole")}
    print(f"#### {title}\n")
    print(f"Truths: {made['six_gaussian']['samples']} samples, seeds "
          f"{made['six_gaussian']['seed']} and {made['six_gaussian']['noise_floor']['seed']}; "
          f"Cycles {made['six_gaussian']['seconds']:.0f} s (six Gaussians' radii) and "
          f"{made['dipole']['seconds']:.0f} s (the dipole's) a seed.\n")
    print("| | vs truth: PSNR dB | SSIM | FLIP | visible | vs reference: PSNR dB | SSIM | FLIP "
          "| visible |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, t in (("noise floor, six Gaussians' truth (seed 2 vs 1)", six),
                    ("noise floor, the dipole's truth (seed 2 vs 1)", dipole)):
        floor = t["noise_floor"]["skin"]
        ceiling = floor["psnr_db"] + 10 * math.log10(2)
        row(name, figures(floor, visible=False)[:3] + [f"ceiling {ceiling:.2f} dB"], ["-"] * 4)
    row("**reference, six Gaussians**", figures(six["reference"]["skin"]), ["-"] * 4)
    row("**reference, dipole** (vs the dipole's truth)", figures(dipole["reference"]["skin"]),
        ["-"] * 4)
    for technique in TECHNIQUES:
        result = load(f"{OUT}/{scene}/run_six_gaussian_{technique}/result.json")
        row(f"`{technique}`", figures(result["truth"]["frame"]["skin"]),
            quality(result["quality"]))
    print()
