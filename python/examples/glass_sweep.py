"""A parametric sweep over the glass's visible transmittance, printing sDA300/50% per variant
(docs/python.md, example 1).

    PYTHONPATH=build/python python3 python/examples/glass_sweep.py [CASE.toml] [T ...]

Each variant is the case's scene with the glass material `pane` rewritten; the case file is copied
beside it with its paths made absolute. Default: cases/sidelit-annual and T = 0.3, 0.5, 0.7.
"""
import math
import pathlib
import re
import sys
import tempfile

import candela


def transmissivity(transmittance):
    """Radiance's glass takes the transmissivity at normal incidence, not the transmittance
    (Radiance reference manual, "Glass": tn = (sqrt(.8402528435 + .0072522239 Tn²) -
    .9166530661) / .0036261119 / Tn)."""
    t = transmittance
    return (math.sqrt(0.8402528435 + 0.0072522239 * t * t) - 0.9166530661) / 0.0036261119 / t


def variant(case_path, transmittance, folder):
    """The case with its glass `pane` at `transmittance`, written into `folder`."""
    case_path = pathlib.Path(case_path).resolve()
    text = case_path.read_text()
    tn = transmissivity(transmittance)
    for rad in re.findall(r'file = "([^"]+\.rad)"', text):
        source = case_path.parent / rad
        scene = re.sub(r"^void glass pane 0 0 3 .*$", f"void glass pane 0 0 3 {tn:.4f} {tn:.4f} {tn:.4f}",
                       source.read_text(), flags=re.M)
        (folder / source.name).write_text(scene)
        text = text.replace(f'"{rad}"', f'"{folder / source.name}"')
    weather = re.search(r'weather = "([^"]+)"', text).group(1)
    text = text.replace(f'"{weather}"', f'"{(case_path.parent / weather).resolve()}"')
    (folder / "case.toml").write_text(text)
    return folder / "case.toml"


def main(argv):
    root = pathlib.Path(__file__).resolve().parents[2]
    case = argv[1] if len(argv) > 1 else root / "cases" / "sidelit-annual" / "case.toml"
    values = [float(v) for v in argv[2:]] or [0.3, 0.5, 0.7]
    print("transmittance  sDA300/50%  ASE1000,250  mean DA300")
    with tempfile.TemporaryDirectory() as tmp:
        for t in values:
            folder = pathlib.Path(tmp) / f"T{t:.2f}"
            folder.mkdir()
            results = candela.load_case(variant(case, t, folder)).run(out=folder / "out")
            g = results.summary["grids"][0]
            print(f"{t:13.2f}  {g['sDA300_50']:9.1f} %  {g['ASE1000_250']:10.1f} %  {g['DA300']:8.1f} %")


if __name__ == "__main__":
    main(sys.argv)
