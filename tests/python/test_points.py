"""candela.illuminance and candela.Scene: closed forms, equality with `candela points`, errors,
warnings, threads and the GIL."""
import math
import subprocess
import threading
import warnings

import numpy as np
import pytest

import candela

UP = [0.0, 0.0, 1.0]


def within(value, expected, error, slack=0.0):
    """|value - expected| within 4 standard errors of the Monte Carlo estimate (plus `slack` for
    what is not Monte Carlo, e.g. printed rounding)."""
    return abs(value - expected) <= 4.0 * error + slack


def test_uniform_sky_closed_forms():
    # A uniform sky of luminance L = E/π over an open plane: a horizontal sensor receives E, a
    # vertical one half of the sky (E/2) and half of the ground, whose luminance is ρ E/π (E/2·ρ).
    e, rho = 12000.0, 0.3
    pts = [[0, 0, 1, 0, 0, 1], [0, 0, 1, 1, 0, 0], [5, 5, 1, 0, -1, 0]]
    lux, err = candela.illuminance(None, pts, sky=candela.Sky.uniform(e, ground_reflectance=rho), seed=3)
    assert lux.shape == (3,) and err.shape == (3,)
    assert within(lux[0], e, err[0], 1e-9 * e)
    for k in (1, 2):
        assert within(lux[k], e * (1 + rho) / 2, err[k], 1e-9 * e)


def test_cie_overcast_vertical_over_horizontal():
    # CIE overcast, L = Lz (1 + 2 sin h)/3: E_h = 7π Lz/9, a vertical plane sees
    # Lz (π/6 + 4/9) of sky, so E_v/E_h = (π/6 + 4/9)/(7π/9) = 0.3961, plus ρ/2 from the ground.
    e, rho = 10000.0, 0.2
    ratio = (math.pi / 6 + 4 / 9) / (7 * math.pi / 9)
    lux, err = candela.illuminance(None, [[0, 0, 0.5, 0, 0, 1], [0, 0, 0.5, 0, 1, 0]],
                                   sky=candela.Sky.cie_overcast(e, ground_reflectance=rho), quality="high")
    assert within(lux[0], e, err[0], 1e-9 * e)
    assert within(lux[1], e * (ratio + rho / 2), err[1], 1e-9 * e)


def test_cie_sky_sun_from_site_and_time():
    # The sun placed by site and time: on a horizontal sensor its direct part is E_n sin(altitude),
    # the altitude candela.sun_position gives; the sky adds its diffuse horizontal illuminance.
    site = candela.Site(48.14, 11.58, timezone=1)
    time = "2026-06-21T13:00"
    sun = candela.sun_position(site, time)
    en, edh = 80000.0, 15000.0
    sky = candela.Sky.cie(12, site, time, direct_normal_illuminance=en, diffuse_horizontal_illuminance=edh)
    no_sun = candela.Sky.cie(12, site, time, sun=False, direct_normal_illuminance=en, diffuse_horizontal_illuminance=edh)
    lux, err = candela.illuminance(None, [[0, 0, 0, 0, 0, 1]], sky=sky)
    diffuse, derr = candela.illuminance(None, [[0, 0, 0, 0, 0, 1]], sky=no_sun)
    direct = en * math.sin(math.radians(sun.altitude_deg))
    assert within(diffuse[0], edh, derr[0], 1e-9 * edh)
    assert within(lux[0], edh + direct, err[0], 1e-6 * direct)


def test_sky_needs_its_time():
    with pytest.raises(candela.InputError):
        candela.illuminance(None, [[0, 0, 0, 0, 0, 1]], sky=candela.Sky.cie_clear(candela.Site(45, 7)))


def small_room_points():
    return np.array([[1.0, 1.5, 0.8, 0, 0, 1], [2.0, 1.5, 0.8, 0, 0, 1], [3.5, 2.5, 0.8, 0, 0, 1],
                     [0.01, 1.5, 1.2, 1, 0, 0], [2.0, 1.5, 2.7, 0, 0, -1]])


def small_room_luminaires(source):
    ies = source / "cases" / "luminaires" / "led_panel_600.ies"
    # The case's [[luminaire]] array: two panels 2 m apart, maintenance factor 0.8.
    return [candela.Luminaire(ies, (x, 1.5, 2.79), maintenance_factor=0.8) for x in (1.0, 3.0)]


def test_same_numbers_as_candela_points(source, candela_exe):
    pts = small_room_points()
    case = source / "cases" / "small-room" / "case.toml"
    stdin = "".join(" ".join(f"{v:.17g}" for v in p) + "\n" for p in pts)
    cli = subprocess.run([candela_exe, "points", "--case", str(case), "--quality", "draft", "--seed", "5",
                          "--threads", "2", "--error"], input=stdin, capture_output=True, text=True, check=True)
    rows = [line.split(",") for line in cli.stdout.splitlines()[1:]]
    cli_lux = np.array([float(r[6]) for r in rows])
    cli_err = np.array([float(r[7]) for r in rows])
    scene = candela.Scene([source / "cases" / "small-room" / "room.rad"])
    lux, err = candela.illuminance(scene, pts, luminaires=small_room_luminaires(source), quality="draft", seed=5,
                                   threads=2)
    # The CLI prints 7 significant digits (error: 3): equal up to that rounding.
    np.testing.assert_allclose(lux, cli_lux, rtol=5e-7, atol=0)
    np.testing.assert_allclose(err, cli_err, rtol=5e-3, atol=0)
    assert (lux > 0).all()


def test_thread_count_does_not_change_results(source):
    scene = candela.Scene([source / "cases" / "small-room" / "room.rad"])
    lum = small_room_luminaires(source)
    one = candela.illuminance(scene, small_room_points(), luminaires=lum, quality="draft", threads=1)
    two = candela.illuminance(scene, small_room_points(), luminaires=lum, quality="draft", threads=2)
    np.testing.assert_array_equal(one[0], two[0])
    np.testing.assert_array_equal(one[1], two[1])


def test_scene_error_names_file_and_line(tmp_path):
    rad = tmp_path / "bad.rad"
    rad.write_text("void plastic grey 0 0 5 .5 .5 .5 0 0\n\ngrey polygon p 0 0 6 0 0 0 1 0 0\n")
    with pytest.raises(candela.InputError) as e:
        candela.Scene([rad])
    assert e.value.file == str(rad)
    assert e.value.line == 3
    assert str(e.value) == f"{rad}:3: {e.value.message}"


def test_bad_points_name_the_row():
    with pytest.raises(candela.InputError) as e:
        candela.illuminance(None, [[0, 0, 0, 0, 0, 1], [0, 0, 0, 0, 0, 0]], sky=candela.Sky.uniform())
    assert (e.value.file, e.value.line) == ("points", 2)
    assert "direction" in e.value.message
    with pytest.raises(candela.InputError) as e:
        candela.illuminance(None, [[0, 0, math.nan, 0, 0, 1]], sky=candela.Sky.uniform())
    assert (e.value.file, e.value.line) == ("points", 1)
    with pytest.raises(candela.InputError):
        candela.illuminance(None, np.zeros((3, 5)), sky=candela.Sky.uniform())


def test_huge_directions_and_luminaire_numbers_are_input_errors(tmp_path):
    # A direction of 1e200 once killed the interpreter inside Embree; aim=(1e200, 0, 0) and
    # multiplier=1e308 ended as internal errors (RuntimeError).
    with pytest.raises(candela.InputError) as e:
        candela.illuminance(None, [[0, 0, 0, 0, 0, 1], [2, 1.5, 0.8, 1e200, 0, 0]], sky=candela.Sky.uniform())
    assert (e.value.file, e.value.line) == ("points", 2)
    assert "cannot be normalised" in e.value.message
    ies = tmp_path / "none.ies"  # the numbers are checked before the file is read
    for kwargs, words in [(dict(aim=(1e200, 0, 0)), "aim"), (dict(multiplier=1e308), "multiplier"),
                          (dict(position=(0, 0, 1e8)), "beyond 1e7 m")]:
        position = kwargs.pop("position", (0, 0, 3))
        with pytest.raises(candela.InputError) as e:
            candela.illuminance(None, [[0, 0, 0, 0, 0, -1]],
                                luminaires=[candela.Luminaire(ies, position, **kwargs)])
        assert words in e.value.message
        assert len(str(e.value)) < 200


def test_missing_luminaire_file_is_an_input_error(tmp_path):
    with pytest.raises(candela.InputError) as e:
        candela.illuminance(None, [[0, 0, 0, 0, 0, -1]], luminaires=[candela.Luminaire(tmp_path / "none.ies", (0, 0, 3))])
    assert "none.ies" in str(e.value)


def test_warnings_go_through_python_warnings(tmp_path):
    rad = tmp_path / "dark.rad"
    rad.write_text("void plastic grey 0 0 5 .5 .5 .5 0 0\ngrey polygon floor 0 0 12 0 0 0 1 0 0 1 1 0 0 1 0\n")
    scene = candela.Scene([rad])
    with pytest.warns(candela.CandelaWarning) as caught:
        lux, _ = candela.illuminance(scene, [[0.5, 0.5, 1, 0, 0, -1]], quality="draft")
    codes = [w.message.code for w in caught]
    assert "no_light_source" in codes
    assert lux[0] == 0.0
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # strict: an InputError before tracing, not a warning
        with pytest.raises(candela.InputError) as e:
            candela.illuminance(scene, [[0.5, 0.5, 1, 0, 0, -1]], strict=True)
    assert "[no_light_source]" in str(e.value)


def test_tracing_releases_the_gil(source):
    # While the engine traces, another Python thread keeps running: it counts far more than the
    # few wake-ups a held GIL would allow (Python switches threads every 5 ms at most).
    scene = candela.Scene([source / "cases" / "small-room" / "room.rad"])
    pts = np.tile(small_room_points(), (40, 1))
    stop = threading.Event()
    count = [0]

    def spin():
        while not stop.is_set():
            count[0] += 1

    t = threading.Thread(target=spin)
    t.start()
    try:
        candela.illuminance(scene, pts, luminaires=small_room_luminaires(source), quality="draft", threads=1)
    finally:
        stop.set()
        t.join()
    assert count[0] > 10000


def test_progress_reaches_the_callback_and_its_exception_stops_the_run(source):
    scene = candela.Scene([source / "cases" / "small-room" / "room.rad"])
    pts = np.tile(small_room_points(), (40, 1))
    calls = []
    candela.illuminance(scene, pts, luminaires=small_room_luminaires(source), quality="draft", threads=1,
                        progress=lambda step, done, total: calls.append((step, done, total)))
    assert calls and calls[-1] == ("tracing", len(pts), len(pts))
    assert all(0 <= d <= t for _, d, t in calls)

    class Stop(Exception):
        pass

    def stop(step, done, total):
        raise Stop()

    with pytest.raises(Stop):
        candela.illuminance(scene, np.tile(pts, (50, 1)), luminaires=small_room_luminaires(source), quality="high",
                            threads=1, progress=stop)
