"""Certify a body, verify the certificate, and plot a small map of the paper's plane.

    python examples/python/certify_and_map.py [OUT.png]

Needs the package with its plotting extra, from the root of a clone:
pip install "./python[plot]" (matplotlib and numpy).
"""

import sys
from fractions import Fraction

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

import chatter  # noqa: E402

N, STEPS = 3, 20
# Point classes of the map, drawn in this order and these colours.
CLASSES = [
    ("certified: no all-down drop separates or ends in PCC", "#1b7837"),
    ("certified: no all-down drop separates (PCC possible)", "#a6dba0"),
    ("CC criterion holds, no certificate", "#fdb863"),
    ("CC criterion fails", "#d9d9d9"),
]


def certify_one():
    """Certify the triangle at kappa = 3/20, gamma = 1/20 and check the certificate."""
    kappa, gamma = Fraction(3, 20), Fraction(1, 20)
    cert = chatter.certify(N, kappa, gamma)
    verdict = chatter.verify(cert.to_ron())
    print(f"{cert}: verified {verdict.ok} ({verdict.claim}, {verdict.max_denominator_bits}-bit denominators)")
    assert verdict.ok
    return kappa, gamma


def point_class(claim, cc):
    if claim == "CompleteChatterFromAllDown":
        return 0
    if claim is not None:
        return 1
    return 2 if cc else 3


def grid():
    """The map over (rho, gamma) in [0, 1]^2, certificates attempted at every point."""
    m = chatter.map(N, rho=(0, 1, STEPS), gamma=(0, 1, STEPS), certify=True)
    print(f"map: {m['points']} points ({m['schema']}), {len(m['disagreements'])} disagreements")
    cols = m["columns"]
    classes = [[0] * STEPS for _ in range(STEPS)]
    for i, (claim, cc) in enumerate(zip(cols["claim"], cols["cc_criterion"])):
        ix, ig = divmod(cols["index"][i], STEPS)  # gamma varies fastest
        classes[ig][ix] = point_class(claim, cc)
    return classes


def plot(classes, marked, out):
    counts = [sum(row.count(c) for row in classes) for c in range(len(CLASSES))]
    print("map:", ", ".join(f"{name}: {k}" for (name, _), k in zip(CLASSES, counts)))
    fig, ax = plt.subplots(figsize=(6.2, 5.2), dpi=150)
    cmap = ListedColormap([c for _, c in CLASSES])
    ax.imshow(classes, origin="lower", extent=(0, 1, 0, 1), cmap=cmap, vmin=-0.5,
              vmax=len(CLASSES) - 0.5, interpolation="nearest", aspect="auto")
    kappa, gamma = marked
    ax.plot(float(kappa) ** 0.5, float(gamma), marker="*", color="black", markersize=13, linestyle="none")
    handles = [
        Patch(facecolor=c, edgecolor="0.4", label=f"{name} ({k} points)")
        for (name, c), k in zip(CLASSES, counts)
        if k > 0
    ]
    handles.append(plt.Line2D([], [], marker="*", color="black", linestyle="none", markersize=11,
                              label=f"certified and verified: κ = {kappa}, γ = {gamma}"))
    ax.legend(handles=handles, loc="upper right", fontsize=7.5, framealpha=0.95)
    ax.set_xlabel(r"$\rho = \sqrt{\kappa}$ (radius of gyration / circumradius)")
    ax.set_ylabel(r"coefficient of restitution $\gamma$")
    ax.set_title(f"Regular triangle (n = {N}): exact certificates on a {STEPS} × {STEPS} grid", fontsize=10)
    fig.tight_layout()
    fig.savefig(out)
    print(f"figure: {out}")


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "chatter_map.png"
    marked = certify_one()
    plot(grid(), marked, out)
