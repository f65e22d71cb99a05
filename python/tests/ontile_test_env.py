"""What the Python test suites share: the module (or why it is missing), the CLI, the demo scene
and an output folder, all from the environment ctest sets (python/CMakeLists.txt)."""
import os
import subprocess
import unittest

try:
    import ontile
    IMPORT_ERROR = None
    # An empty build/python/ontile folder imports as a namespace package: not built either.
    if not hasattr(ontile, "render"):
        raise ImportError(f"{ontile.__path__} holds no built module")
except ImportError as e:  # the extension was not built: every suite skips, saying why
    ontile = None
    IMPORT_ERROR = f"ontile module not importable ({e}); build it with -DONTILE_BUILD_PYTHON=ON"

SOURCE_DIR = os.environ.get("ONTILE_SOURCE_DIR", os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")))
CLI = os.environ.get("ONTILE_CLI", os.path.join(SOURCE_DIR, "build", "ontile"))
DEMO = os.path.join(SOURCE_DIR, "scenes", "demo.glb")
OUTPUT = os.environ.get("ONTILE_TEST_OUTPUT", os.path.join(SOURCE_DIR, "build", "test_output", "python"))


def needs_module(cls):
    return unittest.skipIf(ontile is None, IMPORT_ERROR or "")(cls)


def output_dir(name):
    path = os.path.join(OUTPUT, name)
    os.makedirs(path, exist_ok=True)
    return path


def cli_render(out_dir, name, args):
    """Runs `ontile render` with `args`; returns (PNG bytes, report dict)."""
    import json
    png, report = os.path.join(out_dir, name + ".png"), os.path.join(out_dir, name + ".json")
    subprocess.run([CLI, "render", "--scene", DEMO, "--out", png, "--report", report] + args,
                   check=True, stdout=subprocess.DEVNULL)
    with open(png, "rb") as f, open(report, encoding="utf-8") as r:
        return f.read(), json.load(r)


def without_timing(report):
    """The report minus its wall-clock times (the only part that varies between runs)."""
    return {k: v for k, v in report.items() if k != "timing"}
