"""The Python module (python/trapdem, issue 40) against the program it wraps: the same run from a
dict as from the command line (byte for byte), the strict reader's errors raised with the key,
a run folder read, the analysis equal to `trapdem analyze`'s metrics.json, PIV on synthetic
images, Ctrl-C stopping with a checkpoint and the resume finishing the same run, and two runs in
one process equal. Run by ctest (python.module) with PYTHONPATH=build/python."""
import json
import math
import os
import pathlib
import shutil
import signal
import subprocess
import tempfile
import threading
import tomllib

import numpy as np
import pandas as pd
import pytest

import trapdem

SOURCE = pathlib.Path(os.environ["TRAPDEM_SOURCE_DIR"])
PROGRAM = os.environ["TRAPDEM_EXECUTABLE"]

# A tiny run cut short: a 10 mm pour, short settling and spin-up, 0.5 mm of lowering, snapshots at
# 0 and 0.5 mm (the analysis needs two): about a second on one thread.
SHORT = {"pluviation": {"fill_height": 0.01}, "settling": {"max_time": 0.01}, "spin_up": {"ramp_time": 0.005},
         "trapdoor": {"travel": 0.0005}, "output": {"snapshot_displacements": [0.0, 0.0005]}}
SHORT_SET = ["pluviation.fill_height=0.01", "settling.max_time=0.01", "spin_up.ramp_time=0.005",
             "trapdoor.travel=0.0005", "output.snapshot_displacements=[0.0, 0.0005]"]


def program(*args):
    subprocess.run([PROGRAM, *map(str, args)], check=True, stdout=subprocess.DEVNULL)


@pytest.fixture
def scratch():
    folder = pathlib.Path(tempfile.mkdtemp(prefix="trapdem-python-"))
    yield folder
    shutil.rmtree(folder, ignore_errors=True)


@pytest.fixture(scope="module")
def short_run():
    folder = pathlib.Path(tempfile.mkdtemp(prefix="trapdem-python-run-"))
    yield trapdem.run(SHORT, preset="tiny", out=folder / "run", threads=1)
    shutil.rmtree(folder, ignore_errors=True)


def test_a_run_from_a_dict_is_the_programs_run(scratch, short_run):
    sets = [a for s in SHORT_SET for a in ("--set", s)]
    program("run", "--preset", "tiny", "--out", scratch / "cli", "--threads", 1, "--quiet", *sets)
    expected = (scratch / "cli" / "trapdoor.csv").read_bytes()
    assert (short_run.path / "trapdoor.csv").read_bytes() == expected
    # The whole configuration as a dict (the preset read, changed, written back as TOML): the same.
    with open(SOURCE / "presets" / "tiny.toml", "rb") as f:
        config = tomllib.load(f)
    for table, changes in SHORT.items():
        config[table].update(changes)
    whole = trapdem.run(config, out=scratch / "dict", threads=1)
    assert (whole.path / "trapdoor.csv").read_bytes() == expected
    # And TOML text.
    text = trapdem.run(trapdem.to_toml(config), out=scratch / "text", threads=1)
    assert (text.path / "trapdoor.csv").read_bytes() == expected


def test_a_bad_key_is_raised_with_the_key_named(scratch):
    with pytest.raises(trapdem.InputError, match=r"unknown key box\.widht \(did you mean box\.width\?\)"):
        trapdem.run({"box": {"widht": 0.1}}, preset="tiny", out=scratch / "a")
    with pytest.raises(ValueError, match=r"pluviation\.fill_height = -1\.0.*expected"):
        trapdem.run({"pluviation": {"fill_height": -1.0}}, preset="tiny", out=scratch / "b")
    with open(SOURCE / "presets" / "tiny.toml", "rb") as f:
        config = tomllib.load(f)
    config["contact"]["restitution"] = 2.0
    with pytest.raises(trapdem.InputError, match=r"<dict>.*contact\.restitution = 2.*expected a number in \(0, 1\]"):
        trapdem.run(config, out=scratch / "c")
    with pytest.raises(trapdem.InputError, match="preset 'nosuch'"):
        trapdem.run(preset="nosuch", out=scratch / "d")
    assert not (scratch / "a" / "checkpoint.h5").exists()


def test_a_run_folder_read(short_run):
    grc = short_run.grc
    assert isinstance(grc, pd.DataFrame)
    assert "trapdoor_stress_ratio" in grc.columns and len(grc) > 1
    assert grc["trapdoor_displacement_m"].iloc[-1] == pytest.approx(0.0005, rel=0.05)
    assert short_run.run["complete"] is True
    # The code and the host the run is traced to: this module's build, this CPU, one thread.
    build = trapdem.build_info()
    assert short_run.run["trapdem_commit"] == build["commit"]
    assert short_run.run["trapdem_modified"] == build["modified"]
    assert short_run.run["cpu"] == build["cpu"] and build["cpu"]
    assert short_run.run["threads"] == 1 and short_run.run["ranks"] == 1
    assert short_run.config["box"]["width"] == 0.08
    snapshots = short_run.snapshots
    assert [s["stage"] for s in snapshots][:2] == ["pluviation", "settling"]
    last = short_run.snapshot(-1)
    n = snapshots[-1]["particles"]
    assert last["position"].shape == (n, 3) and last["radius"].shape == (n,)
    assert np.all(np.diff(last["id"]) > 0)  # sorted by id
    assert last["stage"] == "lowering"
    # In the file's order without a copy: read-only maps of snapshots.h5, the same rows.
    mapped = short_run.snapshot(-1, by_id=False)
    for key in ("id", "position", "radius", "velocity", "angular_velocity", "image"):
        assert isinstance(mapped[key], np.memmap) and not mapped[key].flags.writeable, key
        order = np.argsort(mapped[key if key == "id" else "id"], kind="stable")
        assert np.array_equal(mapped[key][order], last[key]), key
    assert mapped["stage"] == "lowering"


def test_the_progress_goes_to_sys_stdout(scratch, capsys):
    # A notebook shows sys.stdout, not the process's file descriptor 1: capsys sees only the former.
    trapdem.run(SHORT, preset="tiny", out=scratch / "loud", threads=1)
    said = capsys.readouterr().out
    assert "stage lowering finished" in said and "finished after" in said
    trapdem.run(SHORT, preset="tiny", out=scratch / "quiet", threads=1, quiet=True)
    assert capsys.readouterr().out == ""


def test_the_analysis_is_the_programs(scratch, short_run):
    program("analyze", short_run.path, "--out", scratch / "analysis", "--no-figures", "--quiet")
    expected = json.loads((scratch / "analysis" / "metrics.json").read_text())
    a = trapdem.analyze(short_run)
    assert a.metrics == expected
    assert a.triangles.shape[1] == 3 and len(a.gamma_max) == len(a.triangles) == len(a.volumetric)
    assert a.reference_positions.shape == a.displacements.shape == (len(a.ids), 2)
    assert a.metrics["strain"]["gamma_max_max"] == pytest.approx(np.nanmax(a.gamma_max), rel=1e-12)
    assert a.settlement_grid.ndim == 2


def test_the_field_history_holds_the_analysis_at_every_snapshot(scratch, short_run):
    program("analyze", short_run.path, "--out", scratch / "analysis", "--no-figures", "--quiet")
    h = trapdem.field_history(scratch / "analysis" / "field_history.h5")
    layers = len(h["snapshot"])
    assert layers >= 1 and np.all(np.diff(h["trapdoor_displacement"]) > 0) and h["trapdoor_displacement"][0] > 0
    for key in ("vertical_displacement", "gamma_max", "volumetric_strain"):
        assert h[key].shape == (layers, len(h["z"]), len(h["x"])) and h[key].dtype == np.float32, key
    # The last layer is the last snapshot's analysis: its settlement grid (half a diameter) holds a
    # node at every node of the history's (one diameter), both being multiples of their spacing.
    a = trapdem.analyze(short_run)
    i = np.rint((h["x"] - a.grid_x0) / a.grid_spacing).astype(int)
    j = np.rint((h["z"] - a.grid_z0) / a.grid_spacing).astype(int)
    assert np.allclose(a.grid_x0 + i * a.grid_spacing, h["x"], rtol=0, atol=1e-12)
    expected = a.settlement_grid[np.ix_(j, i)]
    last = h["vertical_displacement"][-1]
    assert np.array_equal(np.isnan(last), np.isnan(expected))
    assert np.nanmax(np.abs(last - expected)) <= 1e-7 * np.nanmax(np.abs(expected))  # float32 storage
    assert np.nanmin(last) < 0  # the ground above the door settles


def test_piv_on_synthetic_images(scratch):
    images = trapdem.synth("rigid", scratch / "images", size=(160, 160), images=2)
    assert all(p.is_file() for p in images) and (scratch / "images" / "truth.csv").is_file()
    r = trapdem.piv(images, scratch / "piv", threads=1)
    valid = r["zncc"][1] > 0.9
    assert valid.sum() > len(r["x_px"]) // 2
    # The synthetic shift of the last image: (2.5, 1.5) px (src/piv/synthetic_sequence.hpp).
    assert np.all(np.abs(r["u_px"][1][valid] - 2.5) < 0.05)
    assert np.all(np.abs(r["v_px"][1][valid] - 1.5) < 0.05)
    assert (scratch / "piv" / "piv.h5").is_file()
    # The strain of a rigid shift is zero (PIV's ~0.02 px noise over 16 px edges: ~1e-3).
    assert r["total_strain"][0] is None
    rigid = r["total_strain"][1]
    assert rigid["triangles"].shape[1] == 3 and len(rigid["gamma_max"]) == len(rigid["triangles"])
    assert rigid["position"].shape == rigid["displacement"].shape == (len(rigid["subset"]), 2)
    assert np.median(rigid["gamma_max"]) < 2e-3
    # A simple shear of 0.02: gamma_max = gamma (White & Bolton 2004), the median within 10 %.
    sheared = trapdem.synth("shear", scratch / "shear", size=(160, 160), images=2, magnitude=0.02)
    shear = trapdem.piv(sheared, scratch / "piv-shear", threads=1)["total_strain"][1]
    assert np.median(shear["gamma_max"]) == pytest.approx(0.02, rel=0.1)
    assert np.median(np.abs(shear["volumetric"])) < 2e-3


def test_ctrl_c_stops_with_a_checkpoint_and_the_resume_finishes_the_same_run(scratch):
    # The whole tiny preset (several seconds); SIGINT a second in, as Ctrl-C in a notebook.
    timer = threading.Timer(1.0, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    with pytest.raises(KeyboardInterrupt, match="resume"):
        trapdem.run(preset="tiny", out=scratch / "stopped", threads=1)
    timer.join()
    assert (scratch / "stopped" / "checkpoint.h5").is_file()
    assert trapdem.RunFolder(scratch / "stopped").run["complete"] is False
    finished = trapdem.resume(scratch / "stopped", threads=1)
    assert finished.run["complete"] is True
    straight = trapdem.run(preset="tiny", out=scratch / "straight", threads=1)
    assert (finished.path / "trapdoor.csv").read_bytes() == (straight.path / "trapdoor.csv").read_bytes()


def test_two_runs_in_one_process_are_the_same(scratch):
    # The second run after one on two threads: no state of the first (the thread count above all) leaks.
    trapdem.run(SHORT, preset="tiny", out=scratch / "two-threads", threads=2)
    a = trapdem.run(SHORT, preset="tiny", out=scratch / "a", threads=1)
    b = trapdem.run(SHORT, preset="tiny", out=scratch / "b", threads=1)
    assert (a.path / "trapdoor.csv").read_bytes() == (b.path / "trapdoor.csv").read_bytes()


def test_a_figure_of_runs_is_the_programs(scratch, short_run):
    # The strain maps on one scale: the same file as `trapdem figure` writes, the scale it drew.
    program("figure", short_run.path, short_run.path, "--labels", "A", "B", "--out", scratch / "cli.png")
    panel = trapdem.figure([short_run.path, short_run.path], scratch / "py.png", labels=["A", "B"])
    assert panel["out"] == scratch / "py.png" and panel["legend"] is None
    assert (scratch / "py.png").read_bytes() == (scratch / "cli.png").read_bytes()
    assert panel["max_strain"] > 0.0
    fixed = trapdem.figure([short_run.path], scratch / "fixed.svg", max_strain=0.25)
    assert fixed["max_strain"] == 0.25 and (scratch / "fixed.svg").read_text().lstrip().startswith("<?xml")
    # The ground reaction curves: the legend is the run's name.
    curves = trapdem.figure([short_run.path], scratch / "grc.png", grc=True)
    assert curves["max_strain"] is None and curves["legend"] == [short_run.config["name"]]
    assert (scratch / "grc.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    # Bad input, before any analysis: labels not one per folder, a negative scale, no folder.
    with pytest.raises(trapdem.InputError, match=r"--labels: 1 labels for 2 run folders"):
        trapdem.figure([short_run.path, short_run.path], scratch / "x.png", labels=["A"])
    with pytest.raises(trapdem.InputError, match=r"--max-strain -1"):
        trapdem.figure([short_run.path], scratch / "x.png", max_strain=-1.0)
    with pytest.raises(trapdem.InputError, match=r"one or more run folders"):
        trapdem.figure([], scratch / "x.png")
    assert not (scratch / "x.png").exists()


def test_a_study_runs_and_reports(scratch):
    # One case at one scale, the tiny preset cut short: its run, the report and its summary.
    definition = scratch / "sweep.toml"
    definition.write_text(
        'name = "py"\ndefault_scale = "tiny"\n[scales.tiny]\npreset = "tiny"\n[scales.tiny.set]\n'
        + "".join(f"{s.split('=')[0]} = {s.split('=', 1)[1]}\n" for s in SHORT_SET)
        + '[cases.loose]\nlabel = "Loose"\n[cases.loose.set.contact]\nkinetic_friction = 0.3\n'
        + 'static_friction = 0.3\n')
    # A budget of a nanosecond: the run stops with its checkpoint and the call returns unfinished.
    stopped = trapdem.study(definition, out=scratch / "study", threads=1, stop_after=1e-9)
    assert stopped["finished"] is False and stopped["report"] is None and stopped["summary"] is None
    assert (scratch / "study" / "cases" / "loose" / "checkpoint.h5").is_file()
    assert not (scratch / "study" / "report").exists()
    with pytest.raises(ValueError, match="stop_after"):
        trapdem.study(definition, out=scratch / "study", threads=1, stop_after=-1.0)
    result = trapdem.study(definition, out=scratch / "study", threads=1)  # carries it on
    assert result["finished"] is True
    assert result["report"].is_file() and result["report"].name == "index.html"
    assert (scratch / "study" / "cases" / "loose" / "trapdoor.csv").is_file()
    assert "findings" in result["summary"]
    again = trapdem.study(definition, out=scratch / "study", threads=1, report_only=True)
    assert again["report"] == result["report"]
    # cases= and seeds=: a case the study does not have, a seed no run packs with (the tiny preset's
    # is 7), a selection with report_only: refused; the case's own seed runs nothing new.
    with pytest.raises(trapdem.InputError, match="no such case"):
        trapdem.study(definition, out=scratch / "study", threads=1, cases=["dense"])
    with pytest.raises(trapdem.InputError, match="their packing seeds: 7"):
        trapdem.study(definition, out=scratch / "study", threads=1, seeds=[8])
    for bad in ([-1], [True], ["7"]):
        with pytest.raises(ValueError, match="seeds"):
            trapdem.study(definition, out=scratch / "study", threads=1, seeds=bad)
    with pytest.raises(ValueError, match="report_only"):
        trapdem.study(definition, out=scratch / "study", threads=1, report_only=True, cases=["loose"])
    chosen = trapdem.study(definition, out=scratch / "study", threads=1, cases=["loose"], seeds=[7])
    assert chosen["finished"] is True
    assert "finished before, skipped" in (scratch / "study" / "study.log").read_text()
