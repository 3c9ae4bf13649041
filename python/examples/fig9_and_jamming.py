"""Fig. 9 data and a jamming map from Python.

1. Fig. 9 (rigid three-point peg on the hole edge, steady alignment with
   and without precession): runs ``scenes/fig9.toml`` and prints
   N_B1/(m g) against gamma for each precession rate psidot; the full
   table goes to ``OUT/fig9_table.csv``.
2. A jamming map of the compliant planar peg: a sweep of
   ``scenes/insert_compliant.toml`` over Coulomb friction and the radial
   force, each insertion classified by how it ended (``inserted`` event,
   not inserted by t_end, or stopped by the step budget). Locally, or on Dask with ``--scheduler``.

    python python/examples/fig9_and_jamming.py [--out DIR] [--scheduler tcp://host:8786]

With matplotlib installed both are also drawn to ``OUT/*.png``.
"""

import argparse
import os
from pathlib import Path

import numpy as np

import pegdyn

ROOT = Path(__file__).resolve().parents[2]


def fig9(out: Path) -> None:
    r = pegdyn.load(ROOT / "scenes" / "fig9.toml").run()
    c = r.columns
    feasible = np.asarray(c["feasible"]) == 1.0
    print("Fig. 9: N_B1/(m g) at a few gamma values (rad)")
    for psidot in np.unique(c["psidot"]):
        sel = (c["psidot"] == psidot) & feasible
        g, n = c["gamma"][sel], c["N_B1_over_mg"][sel]
        picks = sorted({int(np.argmin(abs(g - x))) for x in (0.05, 0.1, 0.2, 0.3, 0.5)})
        row = "  ".join(f"{g[i]:.3f}: {n[i]:+.4f}" for i in picks)
        print(f"  psidot = {psidot:5.1f} 1/s   {row}")
    header = ",".join(c)
    np.savetxt(out / "fig9_table.csv", np.column_stack([c[k] for k in c]), delimiter=",", header=header, comments="")
    try:
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots()
    for psidot in np.unique(c["psidot"]):
        sel = (c["psidot"] == psidot) & feasible
        ax.plot(c["gamma"][sel], c["N_B1_over_mg"][sel], label=f"psidot = {psidot:g} 1/s")
    ax.set_xscale("log")
    ax.set_xlabel("gamma, rad")
    ax.set_ylabel("N_B1 / (m g)")
    ax.legend()
    fig.savefig(out / "fig9.png", dpi=120)


def jamming_map(out: Path, client=None) -> None:
    scene = pegdyn.load(ROOT / "scenes" / "insert_compliant.toml")
    friction = [0.05, 0.1, 0.15]
    radial = [0.0, 2.5, 5.0, 10.0, 15.0, 20.0]
    rows = pegdyn.sweep(
        scene,
        {"insert_compliant.friction": friction, "insert_compliant.radial_force": radial},
        client=client,
    )
    grid = {}
    for row in rows:
        if row["outcome"] != "ok":
            m = "x"  # stopped unplanned (step budget) or failed
        elif "`inserted`" in (row["stop"] or ""):
            m = "I"
        else:
            m = "."
        grid[row["insert_compliant.friction"], row["insert_compliant.radial_force"]] = m
    print("\nJamming map (I = inserted, . = not inserted by t_end, x = stopped); rows: friction, columns: radial force N")
    print("        " + " ".join(f"{f:7.1f}" for f in radial))
    for mu in friction:
        print(f"  {mu:4.2f}  " + " ".join(f"{grid[mu, f]:>7}" for f in radial))
    keys = ("insert_compliant.friction", "insert_compliant.radial_force", "outcome", "stop")
    lines = [",".join(str(row.get(k)) for k in keys) for row in rows]
    (out / "jamming_map.csv").write_text("friction,radial_force_N,outcome,stop\n" + "\n".join(lines) + "\n")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="out-python")
    ap.add_argument("--scheduler", help="address of a Dask scheduler, e.g. tcp://scheduler:8786")
    args = ap.parse_args()
    out = Path(args.out)
    os.makedirs(out, exist_ok=True)
    fig9(out)
    client = None
    if args.scheduler:
        from dask.distributed import Client

        client = Client(args.scheduler)
    jamming_map(out, client)
    print(f"\nwrote {out}/fig9_table.csv and {out}/jamming_map.csv")


if __name__ == "__main__":
    main()
