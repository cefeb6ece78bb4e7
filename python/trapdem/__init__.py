"""trapdem from Python: run trapdoor experiments, read their folders, analyse them, run PIV.

The calls run trapdem's library (the same code as the ``trapdem`` program) in this process, with
the GIL released while they work; a configuration is checked by the same strict reader, and its
errors are raised as :class:`InputError` (a ``ValueError``) naming the key and what was expected.

    import trapdem
    run = trapdem.run({"pluviation": {"fill_height": 0.02}}, preset="tiny", out="runs/a")
    run.grc                      # the ground reaction curve, a pandas DataFrame
    a = trapdem.analyze(run)     # strain fields (numpy) and metrics (a dict)

docs/python.md has the whole of it.
"""
from __future__ import annotations

import json
import math
import os
import pathlib
import tomllib
from typing import Any, Iterable, Mapping

from . import _trapdem
from ._trapdem import FileError, InputError, SimulationError

__all__ = [
    "InputError", "FileError", "SimulationError", "run", "resume", "RunFolder", "Analysis", "analyze",
    "element", "study", "piv", "synth", "presets", "preset_path", "to_toml", "build_info",
]

_HERE = pathlib.Path(__file__).resolve().parent


def _preset_directory() -> pathlib.Path:
    """The presets: $TRAPDEM_PRESETS, an installed tree's share/trapdem/presets, or the source tree's."""
    if os.environ.get("TRAPDEM_PRESETS"):
        return pathlib.Path(os.environ["TRAPDEM_PRESETS"])
    # Installed: PREFIX/lib/python3/dist-packages/trapdem -> PREFIX/share/trapdem/presets.
    installed = _HERE.parents[3] / "share" / "trapdem" / "presets" if len(_HERE.parents) > 3 else None
    if installed is not None and installed.is_dir():
        return installed
    from . import _paths  # written by the build: the source tree's presets/
    if _paths.SOURCE_PRESETS is None:
        raise InputError(f"no presets found: not in {installed}; set TRAPDEM_PRESETS to a folder of presets")
    return pathlib.Path(_paths.SOURCE_PRESETS)


def presets() -> list[str]:
    """The presets' names (``demo``, ``tiny``, ``paper-calibrated``, ...)."""
    return sorted(p.stem for p in _preset_directory().glob("*.toml"))


def preset_path(name: str) -> pathlib.Path:
    path = _preset_directory() / f"{name}.toml"
    if not path.is_file():
        raise InputError(f"preset '{name}': no such preset in {_preset_directory()} (the presets: {', '.join(presets())})")
    return path


def _toml_value(value: Any, key: str) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if not math.isfinite(value):
            raise InputError(f"{key} = {value}: expected a finite number")
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value)  # a TOML basic string is a JSON string
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_toml_value(v, key) for v in value) + "]"
    if hasattr(value, "tolist"):  # numpy scalars and arrays
        return _toml_value(value.tolist(), key)
    raise InputError(f"{key} = {value!r}: expected a number, a string, a boolean or a list of them")


def to_toml(config: Mapping[str, Any], _prefix: str = "") -> str:
    """A configuration as nested dicts (tables) in TOML text, as trapdem reads it."""
    lines, tables = [], []
    for key, value in config.items():
        if isinstance(value, Mapping):
            tables.append((key, value))
        else:
            lines.append(f"{key} = {_toml_value(value, _prefix + key)}")
    text = "\n".join(lines) + ("\n" if lines else "")
    for key, value in tables:
        name = _prefix + key
        text += f"\n[{name}]\n" + to_toml(value, name + ".")
    return text


def _assignments(changes: Mapping[str, Any], prefix: str = "") -> list[str]:
    """A dict of changes as "key.path=value" assignments, as ``--set`` takes them."""
    out = []
    for key, value in changes.items():
        if isinstance(value, Mapping):
            out += _assignments(value, prefix + key + ".")
        else:
            out.append(f"{prefix}{key}={_toml_value(value, prefix + key)}")
    return out


def _configuration(config, preset: str | None) -> tuple[str, str, str, list[str]]:
    """(TOML text, its name in messages, a file, assignments) from a dict, TOML text or a path; on a
    preset, a dict is its changes, applied and checked as ``--set`` assignments are."""
    if preset is not None:
        if config is not None and not isinstance(config, Mapping):
            raise InputError("give a preset with a dict of changes, or a configuration without a preset")
        return "", "", str(preset_path(preset)), _assignments(config or {})
    if config is None:
        raise InputError("give a configuration (a dict, TOML text or a file) or a preset")
    if isinstance(config, Mapping):
        return to_toml(config), "<dict>", "", []
    if isinstance(config, pathlib.Path) or (isinstance(config, str) and "\n" not in config and "=" not in config):
        if not pathlib.Path(config).is_file():
            raise InputError(f"{config}: no such configuration file")
        return "", "", str(config), []
    return str(config), "<text>", "", []


class RunFolder:
    """A run folder (docs/output.md) read with h5py and pandas: nothing is loaded until asked for."""

    def __init__(self, path):
        self.path = pathlib.Path(path)
        if not (self.path / "resolved.toml").is_file():
            raise InputError(f"{self.path}: not a run folder (no resolved.toml)")

    def __repr__(self):
        return f"RunFolder('{self.path}')"

    def __fspath__(self):
        return str(self.path)

    @property
    def run(self) -> dict:
        """run.json: whether it finished, its particle-steps, wall clock, ..."""
        return json.loads((self.path / "run.json").read_text())

    @property
    def config(self) -> dict:
        """resolved.toml: every parameter the run read, defaults filled in."""
        with open(self.path / "resolved.toml", "rb") as f:
            return tomllib.load(f)

    @property
    def grc(self):
        """trapdoor.csv, the ground reaction curve, as a pandas DataFrame (SI units, named columns)."""
        import pandas
        return pandas.read_csv(self.path / "trapdoor.csv")

    @property
    def snapshots(self) -> list[dict]:
        """Each snapshot's name, stage, time (s), trapdoor displacement (m) and particle count."""
        import h5py
        with h5py.File(self.path / "snapshots.h5", "r") as f:
            return [{"name": name, "stage": g.attrs["stage"], "time_s": float(g.attrs["time"]),
                     "trapdoor_displacement_m": float(g.attrs["trapdoor_displacement"]) + 0.0,
                     "particles": len(g["id"])}
                    for name, g in f["snapshots"].items()]

    def snapshot(self, index: int, *, by_id: bool = True) -> dict:
        """Snapshot `index` (negative from the end) as numpy arrays: id, position (N, 3) m, radius m,
        velocity m/s, angular_velocity rad/s, image, and its attributes (stage, time, ...).

        `by_id` (default): rows sorted by id, so that row k is the same particle in every snapshot
        (rows change order between snapshots); this reads and reorders, a copy. `by_id=False`: the
        file's row order without copying: each dataset trapdem wrote (contiguous, uncompressed) is a
        read-only numpy.memmap of snapshots.h5, read from disk only where it is touched (a million
        particles' positions cost nothing until used); a dataset stored otherwise (chunked or
        compressed by another writer) is read. Each snapshot is a file of its own
        (snapshots/NNNNNN.h5, linked from snapshots.h5) that trapdem writes once and never changes; a
        resume that removes it leaves the maps valid (the file lives on under them)."""
        import h5py
        import numpy
        with h5py.File(self.path / "snapshots.h5", "r") as f:
            names = list(f["snapshots"])
            g = f["snapshots"][names[index]]
            if by_id:
                ids = g["id"][:]
                order = numpy.argsort(ids, kind="stable")
                out = {key: g[key][:][order] for key in g.keys()}
            else:
                out = {key: _mapped(g[key]) for key in g.keys()}
            out.update({key: (v.item() if hasattr(v, "item") else v) for key, v in g.attrs.items()})
            return out


def _mapped(dataset):
    """An HDF5 dataset as a read-only numpy.memmap of the file that holds it (through snapshots.h5's
    external link) when it is one contiguous block (no filter, no chunks: HDF5 then stores it as
    plain bytes at get_offset()), else read."""
    import numpy
    offset = dataset.id.get_offset()
    if offset is None or dataset.chunks is not None or dataset.compression is not None or dataset.size == 0:
        return dataset[()]
    return numpy.memmap(dataset.file.filename, dtype=dataset.dtype, mode="r", offset=offset, shape=dataset.shape)


def run(config=None, *, preset: str | None = None, out=None, overrides: Iterable[str] = (), threads: int = 0,
        quiet: bool = False, stop_after: float = 0.0) -> RunFolder:
    """Runs a trapdoor experiment into `out` (a new folder) and returns it.

    `config` is a dict (tables as nested dicts), TOML text or a file; with `preset` it is a dict of
    changes to that preset (applied as ``--set`` assignments). `overrides` are "key.path=value"
    strings as ``--set``. `threads`: 0 is the configuration's numerics.threads, else all cores. The
    run's progress lines go to sys.stdout (a notebook shows them in the cell), its warnings to
    sys.stderr; `quiet` keeps the progress in run.log only. `stop_after` (s of wall clock) stops it
    with a checkpoint. Ctrl-C (KeyboardInterrupt) stops it with a checkpoint too, as the program
    does; :func:`resume` carries it on."""
    text, name, file, changes = _configuration(config, preset)
    finished = _trapdem.run(text, name, file, changes + list(overrides), str(out or ""), "", [], threads, quiet,
                            stop_after)
    folder = RunFolder(out) if out else None
    if not finished and stop_after <= 0.0:
        raise KeyboardInterrupt(f"the run stopped with a checkpoint; carry it on with trapdem.resume({str(out)!r})")
    return folder


def resume(folder, *, allow_change: Iterable[str] = (), overrides: Iterable[str] = (), threads: int = 0,
           quiet: bool = False, stop_after: float = 0.0) -> RunFolder:
    """Carries on a run from its checkpoint (as ``trapdem run --resume``)."""
    path = str(pathlib.Path(folder))
    finished = _trapdem.run("", "", "", list(overrides), "", path, list(allow_change), threads, quiet, stop_after)
    if not finished and stop_after <= 0.0:
        raise KeyboardInterrupt(f"the run stopped with a checkpoint; carry it on with trapdem.resume({path!r})")
    return RunFolder(path)


class Analysis:
    """A run's analysis: `metrics` (metrics.json's dict) and the fields as numpy arrays: `ids`,
    `reference_positions` and `displacements` (N, 2: x, z in m), `triangles` (M, 3 node indices),
    `gamma_max`, `gamma_max_smoothed`, `volumetric` (per triangle), `settlement_grid` (nz, nx, m,
    downward negative as w) with `grid_x0`, `grid_z0`, `grid_spacing` (m)."""

    def __init__(self, fields: dict):
        self.metrics = json.loads(fields.pop("metrics_json"))
        self.written = [pathlib.Path(p) for p in fields.pop("written")]
        self.__dict__.update(fields)

    def __repr__(self):
        zone = self.metrics.get("zone_of_influence", {})
        return f"Analysis(shape_ratio={zone.get('shape_ratio')}, triangles={len(self.triangles)})"


def analyze(folder, *, at: str = "", reference: str = "0mm", view: str = "front", incremental: bool = False,
            smoothing: float = 2.0, write: bool = False, figures: bool = False, format: str = "png") -> Analysis:
    """The analysis of `trapdem analyze` (at the last snapshot unless `at`, e.g. "10mm"); with
    `write` its files go to FOLDER/analysis (with the figures if `figures`), as the program's."""
    return Analysis(_trapdem.analyze(str(pathlib.Path(folder)), at, reference, view, incremental, smoothing, write,
                                     figures, format))


def build_info() -> dict:
    """The code this module was built from and the host it runs on, as each run's run.json records
    them: `commit` (the full hash; empty outside a git checkout), `modified` (tracked files differed
    from it when built), `description` ("7a62e4e1c2d3", "... with uncommitted changes") and `cpu`
    (/proc/cpuinfo's name with family, model and AVX-512 or AVX2)."""
    return _trapdem.build_info()


def field_history(path) -> dict:
    """Every snapshot's fields on one grid (analysis/field_history.h5, docs/analysis.md), from that
    file or from a run folder (FOLDER/analysis/field_history.h5, written by ``trapdem analyze``):
    `x` (nx), `z` (nz) in m; per layer (one per snapshot after the reference) `snapshot`,
    `trapdoor_displacement` (m); `vertical_displacement` (m, up positive), `gamma_max` and
    `volumetric_strain` (compression positive) as float32 arrays (layers, nz, nx), NaN where no
    kept triangle covers a node; and `case`, `view`, `mean_diameter`, `reference_snapshot`."""
    path = pathlib.Path(path)
    if path.is_dir():
        path = path / "analysis" / "field_history.h5"
    return _trapdem.field_history(str(path))


def element(config=None, *, preset: str | None = None, out=None, overrides: Iterable[str] = (),
            threads: int = 0) -> dict:
    """The virtual element test (docs/element.md) into `out`: the friction angles per confining stress."""
    file = str(config) if config is not None else str(preset_path(preset or "demo"))
    if isinstance(config, Mapping):
        raise InputError("element: give a configuration file or a preset (with overrides)")
    return _trapdem.element(file, list(overrides), str(out or ""), threads)


def figure(folders: Iterable, out, *, grc: bool = False, labels: Iterable[str] = (), at: str = "",
           reference: str = "0mm", view: str = "front", max_strain: float = 0.0) -> dict:
    """Several run folders in one figure, as ``trapdem figure``: their maximum shear strain maps side by
    side on one colour scale and one length scale (each analysed in memory at `at`, e.g. "80mm",
    default each run's last snapshot, from `reference`), or with `grc` their ground reaction curves on
    one chart. `out`'s extension picks PNG, SVG or PDF; `labels` titles the panels (default: the runs'
    names); `max_strain` the top of the colour scale (0: the largest of the runs' own). Returns the
    file (`out`), the scale drawn (`max_strain`; None for the curves) and the curves' `legend`
    entries (None for the maps)."""
    r = _trapdem.figure([str(pathlib.Path(f)) for f in folders], str(out), grc, list(labels), at, reference, view,
                        max_strain)
    return {"out": pathlib.Path(out), "max_strain": r["max_strain"],
            "legend": None if r["legend"] is None else list(r["legend"])}


def study(file, *, scale: str = "", out=None, threads: int = 0, quiet: bool = False, report_only: bool = False,
          stop_after: float = 0.0, cases: Iterable[str] = (), seeds: Iterable[int] = ()) -> dict:
    """A study (docs/study.md) run, resumed (its finished runs skipped) and reported into `out`
    (default trapdem-out/<study>-<scale>), as ``trapdem study``: returns the folder, the report's
    page and its summary (summary.json as a dict), and `finished` True. Its lines and its runs'
    progress go to sys.stdout unless `quiet` (then to study.log and each run.log only). Ctrl-C stops
    it with its running case's checkpoint and raises KeyboardInterrupt; calling it again carries on.
    `stop_after` (s of wall clock, from its first run's start; as ``--stop-after``) stops it the same
    way but returns, with `finished` False and no report or summary (None). `cases` and `seeds` (as
    ``--case`` and ``--seed``) run only those cases' runs and those packing seeds, leaving the others
    as they are; the report covers every finished run."""
    if stop_after < 0.0 or (report_only and stop_after > 0.0):
        raise ValueError(f"stop_after = {stop_after!r}: expected seconds > 0 for the runs (0: no budget), "
                         "not with report_only")
    cases, seeds = [str(c) for c in cases], list(seeds)
    if report_only and (cases or seeds):
        raise ValueError("cases, seeds: choose the runs run here, not with report_only (the report covers every "
                         "finished run)")
    for seed in seeds:
        if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
            raise ValueError(f"seeds: {seed!r}: expected a packing seed, an integer >= 0")
    r = _trapdem.study(str(file), scale, str(out or ""), str(_preset_directory()), threads, quiet, report_only,
                       stop_after, cases, seeds)
    if not r["finished"]:
        if stop_after > 0.0:
            return {"out": pathlib.Path(r["out"]), "report": None, "summary": None, "finished": False}
        raise KeyboardInterrupt(f"the study stopped with a checkpoint; call trapdem.study again to carry it on")
    page = pathlib.Path(r["report"])
    return {"out": pathlib.Path(r["out"]), "report": page,
            "summary": json.loads((page.parent / "summary.json").read_text()), "finished": True}


def piv(images: Iterable, out, *, subset: int = 32, step: int = 16, threads: int = 0, scale: float | None = None,
        origin=None, figures: bool = False) -> dict:
    """PIV over photographs (in order) into `out` (displacements.csv, piv.h5): subset centres `x_px`,
    `y_px` and per image and subset `u_px`, `v_px` (displacement from image 1, y down) and `zncc`;
    and per image the strain (the DEM analysis' constant strain triangles over the valid subset
    centres, as piv.h5 has it): `total_strain[k]` from image 1 and `incremental_strain[k]` from
    image k-1, each None for image 1, else a dict of `position` and `displacement` (N, 2: x, z up,
    in `unit`), `triangles` (M, 3), `gamma_max` and `volumetric` (per triangle, compression
    positive), `subset` (each node's subset index)."""
    return _trapdem.piv([str(p) for p in images], str(out), subset, step, threads, scale, list(origin or []), figures)


def synth(field: str, out, *, size=(512, 512), images: int = 2, noise: float = 2.0, magnitude: float | None = None,
          seed: int = 1) -> list[pathlib.Path]:
    """Synthetic speckle images under a known field (rigid, strain, shear, trapdoor) with truth.csv."""
    count = _trapdem.synth(field, str(out), int(size[0]), int(size[1]), images, noise, magnitude, seed)
    return [pathlib.Path(out) / f"image_{k:03d}.png" for k in range(1, count + 1)]
