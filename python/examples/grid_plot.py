"""A grid study whose results are plotted with matplotlib when it is installed, else printed
(docs/python.md, example 2).

    PYTHONPATH=build/python python3 python/examples/grid_plot.py [CASE.toml] [OUT.png]

Runs the case (default cases/small-room) and shows its first grid: a false-colour plan of the
illuminance with each point's value, or a text table when matplotlib is missing.
"""
import pathlib
import sys
import tempfile

import candela


def main(argv):
    root = pathlib.Path(__file__).resolve().parents[2]
    case = candela.load_case(argv[1] if len(argv) > 1 else root / "cases" / "small-room" / "case.toml")
    with tempfile.TemporaryDirectory() as tmp:
        results = case.run(out=pathlib.Path(tmp) / "out")
        grid = next(iter(results.grids.values()))
        x, y = grid.positions[:, 0], grid.positions[:, 1]
        lux, err = grid.illuminance, grid.error
        stats = results.summary["grids"][0]
        print(f"{case.name}, grid '{grid.name}': {len(lux)} points, Eavg {stats['average']:.0f} lx, "
              f"Emin {stats['minimum']:.0f} lx, U0 {stats['u0']:.2f}; largest standard error {err.max():.1f} lx")
        try:
            import matplotlib
            matplotlib.use("Agg")
            import matplotlib.pyplot as plt
        except ImportError:
            print("    x m     y m      lux   ± lx")
            for row in zip(x, y, lux, err):
                print("{:7.2f} {:7.2f} {:8.1f} {:6.1f}".format(*row))
            return
        fig, ax = plt.subplots(figsize=(6, 4.5))
        points = ax.scatter(x, y, c=lux, cmap="viridis", s=400, marker="s")
        for xi, yi, v in zip(x, y, lux):
            ax.annotate(f"{v:.0f}", (xi, yi), ha="center", va="center", fontsize=7, color="white")
        fig.colorbar(points, label="illuminance (lx)")
        ax.set(xlabel="x (m)", ylabel="y (m)", title=f"{case.name}: {grid.name}", aspect="equal")
        out = argv[2] if len(argv) > 2 else "grid.png"
        fig.savefig(out, dpi=120, bbox_inches="tight")
        print(f"plan: {out}")


if __name__ == "__main__":
    main(sys.argv)
