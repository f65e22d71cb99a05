"""Sweeps on Dask: `python3 -m ontile.sweep CONFIG.json` renders every configuration of a grid of
scenes x pipelines x sizes x settings, one Dask task per configuration, on a `LocalCluster` of
worker processes (default) or on a running cluster (`--scheduler ADDRESS`), and writes one table
(CSV and/or JSON) sorted by configuration. Every value in the table is a deterministic output of
ontile (bytes per category, image and report digests), so the table is identical whichever
worker ran what; wall-clock times are added only with --timings (docs/scaling.md).

CONFIG (JSON):
    {"scenes": ["demo.glb"],             # relative to the config file's folder
     "pipelines": ["lambert", "cartoon"],
     "sizes": [[160, 90]],                # optional, default [[1280, 720]]
     "threads": 1,                        # per task (optional, default 1)
     "options": {"render_graph": "off"},  # ontile.render options every configuration shares
     "grid": {"tile": [16, 32], "set.msaa": [1, 4]}}   # axes: option name, or set.KEY for --set
"""
import argparse
import csv
import hashlib
import importlib
import io
import itertools
import json
import os
import sys
import tempfile
import time

# The table's fixed columns, then the grid axes (sorted), then the byte categories (sorted).
FIXED_COLUMNS = ["scene", "pipeline", "width", "height"]
RESULT_COLUMNS = ["bytes_read", "bytes_written", "passes", "image_sha256", "report_sha256"]


class ConfigError(Exception):
    """A configuration file that cannot be used: reported as `error: FILE: problem`, exit 2."""


def _require(condition, problem):
    if not condition:
        raise ConfigError(problem)


def load_config(path):
    """The configuration's list of tasks, each a dict: scene (as written), scene_path (resolved),
    pipeline, width, height, threads, options (ontile.render's), axes ({axis: value})."""
    try:
        with open(path, encoding="utf-8") as f:
            config = json.load(f)
    except OSError as e:
        raise ConfigError(e.strerror or str(e)) from None
    except json.JSONDecodeError as e:
        raise ConfigError(f"invalid JSON: {e}") from None
    _require(isinstance(config, dict), "expected a JSON object")
    known = {"scenes", "pipelines", "sizes", "threads", "options", "grid"}
    unknown = sorted(set(config) - known)
    _require(not unknown, f"unknown key '{unknown[0] if unknown else ''}' (valid: {', '.join(sorted(known))})")
    scenes, pipelines = config.get("scenes"), config.get("pipelines")
    _require(isinstance(scenes, list) and scenes and all(isinstance(s, str) for s in scenes),
             "'scenes': expected a non-empty list of scene files")
    _require(isinstance(pipelines, list) and pipelines and all(isinstance(p, str) for p in pipelines),
             "'pipelines': expected a non-empty list of pipeline names")
    sizes = config.get("sizes", [[1280, 720]])
    _require(isinstance(sizes, list) and sizes and all(
        isinstance(s, list) and len(s) == 2 and all(isinstance(v, int) and v > 0 for v in s) for s in sizes),
        "'sizes': expected a list of [width, height] pairs of positive integers")
    threads = config.get("threads", 1)
    _require(isinstance(threads, int) and 0 <= threads <= 1024, "'threads': expected an integer 0..1024")
    shared = config.get("options", {})
    _require(isinstance(shared, dict), "'options': expected an object of ontile.render options")
    grid = config.get("grid", {})
    _require(isinstance(grid, dict) and all(isinstance(v, list) and v for v in grid.values()),
             "'grid': expected an object of non-empty value lists")
    axes = sorted(grid)
    folder = os.path.dirname(os.path.abspath(path))
    tasks = []
    for scene, pipeline, size, values in itertools.product(
            scenes, pipelines, sizes, itertools.product(*(grid[a] for a in axes))):
        options = json.loads(json.dumps(shared))  # a deep copy per task
        for axis, value in zip(axes, values):
            if axis.startswith("set."):
                options.setdefault("set", {})[axis[4:]] = value
            else:
                options[axis] = value
        tasks.append({"scene": scene, "scene_path": os.path.join(folder, scene), "pipeline": pipeline,
                      "width": size[0], "height": size[1], "threads": threads, "options": options,
                      "axes": dict(zip(axes, values))})
    return tasks


_scenes = {}  # per worker process: each scene file is loaded once, whatever number of tasks


def render_configuration(task, timings=False):
    """Renders one configuration (a Dask task) and returns its table row."""
    import ontile
    scene = _scenes.get(task["scene_path"])
    if scene is None:
        scene = _scenes[task["scene_path"]] = ontile.load_scene(task["scene_path"])
    start = time.perf_counter()
    result = ontile.render(scene, pipeline=task["pipeline"], size=(task["width"], task["height"]),
                           threads=task["threads"], options=task["options"])
    elapsed_ms = (time.perf_counter() - start) * 1000.0
    report = result.report
    # The digest covers everything deterministic: the report without its timings, with the scene
    # named as the configuration names it (workers may see it under another absolute path).
    report.pop("timing", None)
    report["run"]["scene"] = task["scene"]
    row = {"scene": task["scene"], "pipeline": task["pipeline"], "width": task["width"], "height": task["height"]}
    row.update({axis: _cell(value) for axis, value in task["axes"].items()})
    row.update({"bytes_read": report["frame"]["bytes_read"], "bytes_written": report["frame"]["bytes_written"],
                "passes": len(report["passes"]),
                "image_sha256": hashlib.sha256(result.image.tobytes()).hexdigest(),
                "report_sha256": hashlib.sha256(json.dumps(report, sort_keys=True).encode()).hexdigest()})
    row.update({f"bytes.{name}": value for name, value in report["frame"]["by_category"].items()})
    if timings:
        row["render_ms"] = round(elapsed_ms, 3)
    return row


def _cell(value):
    return value if isinstance(value, (int, float, str)) else json.dumps(value, sort_keys=True)


def _sort_key(row, axes):
    return tuple(str(row[c]) if not isinstance(row[c], int) else f"{row[c]:012d}" for c in FIXED_COLUMNS + axes)


def make_table(tasks, rows):
    """Rows sorted by configuration, with one column list for all (missing categories are 0)."""
    axes = sorted({a for t in tasks for a in t["axes"]})
    categories = sorted({k for r in rows for k in r if k.startswith("bytes.")})
    timing = ["render_ms"] if any("render_ms" in r for r in rows) else []
    columns = FIXED_COLUMNS + axes + RESULT_COLUMNS + categories + timing
    table = [{c: r.get(c, 0) for c in columns} for r in rows]
    table.sort(key=lambda r: _sort_key(r, axes))
    return columns, table


def run_serial(tasks, timings=False):
    return [render_configuration(t, timings) for t in tasks]


def run_dask(tasks, workers=None, scheduler=None, timings=False):
    """One task per configuration on a LocalCluster of `workers` single-threaded processes, or on
    the cluster at `scheduler`; results come back in submission order whoever ran them."""
    from dask.distributed import Client, LocalCluster
    import ontile.sweep as sweep  # by its module name: workers unpickle the task function by name
    if scheduler:
        client, cluster = Client(scheduler), None
    else:
        n_workers = workers or min(len(tasks), os.cpu_count() or 1)
        cluster = LocalCluster(n_workers=n_workers, threads_per_worker=1, processes=True,
                               dashboard_address=None)
        client = Client(cluster)
    try:
        # A worker that cannot import ontile could not even unpickle a task (which would then
        # wait forever): check every worker first, so that the error comes back here.
        client.run(importlib.import_module, "ontile.sweep")
        futures = client.map(sweep.render_configuration, tasks, timings=timings, pure=False)
        return client.gather(futures)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


def csv_text(columns, table):
    out = io.StringIO()
    writer = csv.DictWriter(out, fieldnames=columns, lineterminator="\n")
    writer.writeheader()
    writer.writerows(table)
    return out.getvalue()


def json_text(columns, table):
    return json.dumps({"format": "ontile-sweep", "columns": columns, "rows": table}, indent=2) + "\n"


def _write_together(files):
    """Writes every (path, text) to a temporary file beside it, then renames them all: a failure
    leaves none of the outputs half-written (the CLI's contract, README "The CLI")."""
    staged = []
    try:
        for path, text in files:
            fd, temporary = tempfile.mkstemp(dir=os.path.dirname(os.path.abspath(path)), prefix=".ontile-sweep-")
            staged.append(temporary)
            with os.fdopen(fd, "w", encoding="utf-8") as f:
                f.write(text)
                f.flush()
                os.fsync(f.fileno())
        for (path, _), temporary in zip(files, staged):
            os.replace(temporary, path)
    finally:
        for temporary in staged:
            if os.path.exists(temporary):
                os.unlink(temporary)


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m ontile.sweep", description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("config", help="the grid (JSON; see docs/scaling.md)")
    parser.add_argument("--csv", help="write the table here as CSV (- for standard output)")
    parser.add_argument("--json", help="write the table here as JSON (- for standard output)")
    parser.add_argument("--workers", type=int, help="LocalCluster worker processes (default: one per core)")
    parser.add_argument("--scheduler", help="address of a running dask scheduler, e.g. tcp://host:8786")
    parser.add_argument("--serial", action="store_true", help="render in this process, without Dask")
    parser.add_argument("--timings", action="store_true",
                        help="add each task's render_ms (wall clock; varies from run to run)")
    args = parser.parse_args(argv)
    if args.workers is not None and args.workers < 1:
        parser.error("--workers: expected at least 1")
    if args.serial and (args.scheduler or args.workers):
        parser.error("--serial runs without Dask: no --scheduler or --workers")
    for option, path in (("--csv", args.csv), ("--json", args.json)):
        if path and path != "-" and not os.path.isdir(os.path.dirname(os.path.abspath(path))):
            print(f"error: {option} {path}: the folder does not exist", file=sys.stderr)
            return 2
    try:
        tasks = load_config(args.config)
    except ConfigError as e:
        print(f"error: {args.config}: {e}", file=sys.stderr)
        return 2
    try:
        rows = run_serial(tasks, args.timings) if args.serial else run_dask(
            tasks, args.workers, args.scheduler, args.timings)
    except ValueError as e:  # ontile.Error: a scene, pipeline or option the config names is bad
        print(f"error: {args.config}: {e}", file=sys.stderr)
        return 2
    except Exception as e:  # the cluster: unreachable, or workers that cannot import ontile
        where = f"--scheduler {args.scheduler}" if args.scheduler else "LocalCluster"
        print(f"error: {where}: {type(e).__name__}: {e}", file=sys.stderr)
        return 2
    columns, table = make_table(tasks, rows)
    outputs = [(args.csv, csv_text), (args.json, json_text)]
    if not args.csv and not args.json:
        outputs = [("-", csv_text)]
    _write_together([(path, text(columns, table)) for path, text in outputs if path and path != "-"])
    for path, text in outputs:
        if path == "-":
            sys.stdout.write(text(columns, table))
    print(f"{len(table)} configurations", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
