"""candela.load_case and Case.run: the same files as `candela run`, arrays that are those files,
the annual memmap, errors, warnings and Ctrl-C."""
import csv
import json
import os
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import candela


def read_csv_columns(path):
    """An independent reading of a results CSV (the csv module, not numpy)."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return {name: np.array([float(r[k]) for r in rows[1:]]) for k, name in enumerate(rows[0])}


def test_run_gives_the_command_lines_files_and_arrays(source, candela_exe, tmp_path):
    case = source / "cases" / "small-room" / "case.toml"
    subprocess.run([candela_exe, "run", str(case), "--out", str(tmp_path / "cli"), "--quality", "draft", "--seed", "7",
                    "--threads", "2", "--quiet"], check=True)
    c = candela.load_case(case)
    assert (c.name, c.grids, c.annual) == ("Small room", ["workplane", "desk"], False)
    r = c.run(out=tmp_path / "py", quality="draft", seed=7, threads=1)
    assert list(r.grids) == ["workplane", "desk"]
    for name in r.grids:
        # Same inputs and seed: the very same bytes, whatever the thread count.
        assert (tmp_path / "py" / f"{name}.csv").read_bytes() == (tmp_path / "cli" / f"{name}.csv").read_bytes()
        g = r.grids[name]
        cols = read_csv_columns(tmp_path / "cli" / f"{name}.csv")
        np.testing.assert_array_equal(g.positions, np.column_stack([cols["x"], cols["y"], cols["z"]]))
        np.testing.assert_array_equal(g.normals, np.column_stack([cols["dx"], cols["dy"], cols["dz"]]))
        np.testing.assert_array_equal(g.illuminance, cols["illuminance_lux"])
        np.testing.assert_array_equal(g.error, cols["error_lux"])
        assert g.hourly is None
    cli_summary = json.loads((tmp_path / "cli" / "summary.json").read_text())
    for mine, theirs in zip(r.summary["grids"], cli_summary["grids"]):
        assert mine == theirs
    # The summary's average is the mean of the values, to the CSV's 8 significant digits.
    wp = r.grids["workplane"]
    assert r.summary["grids"][0]["average"] == pytest.approx(wp.illuminance.mean(), rel=1e-7)
    assert r.summary["grids"][0]["points"] == len(wp.illuminance) == 24


def test_run_defaults_to_the_cases_output_folder(source, tmp_path):
    text = (source / "cases" / "small-room" / "case.toml").read_text()
    text = text.replace('"room.rad"', json.dumps(str(source / "cases" / "small-room" / "room.rad")))
    text = text.replace('"../luminaires/', '"' + str(source / "cases" / "luminaires") + "/")
    text = text.replace('"sensors.pts"', json.dumps(str(source / "cases" / "small-room" / "sensors.pts")))
    text = text.replace('dir = "../../out/small-room"', 'dir = "results"')
    (tmp_path / "case.toml").write_text(text)
    r = candela.load_case(tmp_path / "case.toml").run(quality="draft")
    assert os.path.samefile(r.out_dir, tmp_path / "results")
    assert (tmp_path / "results" / "report.html").exists()


ANNUAL = "tests/cli/run/annual/case.toml"


def test_annual_hourly_results_are_a_read_only_memmap(source, tmp_path):
    r = candela.load_case(source / ANNUAL).run(out=tmp_path / "a")
    assert r.annual
    g = r.grids["desk"]
    h = g.hourly
    assert isinstance(h, np.memmap) and h.dtype == np.float32 and h.shape == (9, 8760)
    assert os.path.samefile(h.filename, tmp_path / "a" / "desk_hourly.f32")
    assert not h.flags.writeable
    with pytest.raises(ValueError):
        h[0, 0] = 1.0
    # Against the file read independently: header, stamps and data (docs/annual-outputs.md).
    raw = (tmp_path / "a" / "desk_hourly.f32").read_bytes()
    offset = int.from_bytes(raw[12:16], "little")
    assert offset == 48 + 4 * 8760
    np.testing.assert_array_equal(h, np.frombuffer(raw, dtype="<f4", offset=offset).reshape(9, 8760))
    assert tuple(g.hour_stamps[0]) == (1, 1, 1) and tuple(g.hour_stamps[-1]) == (12, 31, 24)
    # Per sensor, the hours of the year with direct sun, recomputed from the direct-sun memmap,
    # are the annual CSV's sun_hours (docs/annual-outputs.md).
    sun = g.direct_sun_hourly
    assert isinstance(sun, np.memmap) and sun.shape == h.shape
    np.testing.assert_array_equal((sun > 0).sum(axis=1), g.annual["sun_hours"])
    assert (h >= sun).all()  # the total contains the direct sun
    assert g.direct_sun_hourly.shape == h.shape


def test_case_errors_name_the_line(tmp_path):
    (tmp_path / "case.toml").write_text('[case]\nname = "x"\n\n[settings]\nquality = "draft"\ncolour = 3\n')
    with pytest.raises(candela.InputError) as e:
        candela.load_case(tmp_path / "case.toml")
    assert (os.path.basename(e.value.file), e.value.line) == ("case.toml", 6)
    assert str(e.value).startswith(f"{e.value.file}:6: ")


def test_case_warnings_and_strict(source, tmp_path):
    rad = source / "cases" / "small-room" / "room.rad"
    (tmp_path / "case.toml").write_text(textwrap.dedent(f"""\
        [[scene]]
        file = {json.dumps(str(rad))}
        [[grid]]
        name = "floor"
        corners = [[0.0, 0.0], [4.0, 3.0]]
        height = 0.8
        spacing = 1.0
        [settings]
        quality = "draft"
        """))
    c = candela.load_case(tmp_path / "case.toml")
    with pytest.warns(candela.CandelaWarning) as caught:
        r = c.run(out=tmp_path / "out")
    assert "no_light_source" in [w.message.code for w in caught]
    assert "no_light_source" in [w.code for w in r.warnings]
    assert "no_light_source" in [w["code"] for w in r.summary["warnings"]]
    with pytest.raises(candela.InputError):
        c.run(out=tmp_path / "strict", strict=True)
    assert not (tmp_path / "strict").exists()


INTERRUPTED = textwrap.dedent("""\
    import sys, candela
    def progress(step, done, total):
        if step == "tracing":
            print("tracing", flush=True)
    candela.load_case(sys.argv[1]).run(out=sys.argv[2], quality="high", threads=1, progress=progress)
    print("finished", flush=True)
    """)


def test_ctrl_c_stops_the_run_and_keeps_the_previous_result(source, tmp_path):
    # A case slow enough to be interrupted: the small room's grid at 2 cm spacing, high quality.
    text = (source / "cases" / "small-room" / "case.toml").read_text()
    case = source / "cases" / "small-room" / "slow.toml"
    slow = tmp_path / "slow.toml"
    slow.write_text(text.replace("spacing = 0.5", "spacing = 0.02")
                    .replace('"room.rad"', json.dumps(str(source / "cases" / "small-room" / "room.rad")))
                    .replace('"../luminaires/', '"' + str(source / "cases" / "luminaires") + "/")
                    .replace('"sensors.pts"', json.dumps(str(source / "cases" / "small-room" / "sensors.pts"))))
    out = tmp_path / "out"
    candela.load_case(source / "cases" / "small-room" / "case.toml").run(out=out, quality="draft")
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    script = tmp_path / "interrupted.py"
    script.write_text(INTERRUPTED)
    proc = subprocess.Popen([sys.executable, str(script), str(slow), str(out)], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, env=os.environ.copy())
    assert proc.stdout.readline().strip() == "tracing"
    time.sleep(0.5)
    proc.send_signal(signal.SIGINT)
    # It stopped, not finished (the whole run takes minutes; a run that ignored the signal would
    # print "finished" or outlast the timeout). No bound on how fast: a loaded machine is slower.
    stdout, stderr = proc.communicate(timeout=120)
    assert proc.returncode != 0
    assert "KeyboardInterrupt" in stderr and "finished" not in stdout
    # The folder holds the previous result, byte for byte, and nothing was left beside it.
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["interrupted.py", "out", "slow.toml"]
    assert not case.exists()
