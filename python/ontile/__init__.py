"""ontile from Python: load glTF scenes, render them with any registered pipeline or with a
pipeline written in Python, and get the image as a NumPy array and the traffic report as the
dict `ontile render --report` writes (docs/python.md).

    import ontile
    scene = ontile.load_scene("scenes/demo.glb")
    result = ontile.render(scene, pipeline="cartoon", size=(320, 180), options={"tile": 32})
    result.image          # numpy uint8 (height, width, 4); float32 for float targets
    result.report["frame"]["bytes_read"]
"""
import json

from ._ontile import (  # noqa: F401  (the public names of the extension)
    Attachment, CameraMatrices, CullingResults, Error, Frame, GraphPassBuilder, GraphPassRecorder,
    GraphResource, Material, RenderGraph, Scene, ShaderLibrary, Surface, __version__, load_scene,
    pipeline_description, shader_library_names)
from . import _ontile

__all__ = ["Attachment", "Error", "Frame", "Pipeline", "RenderResult", "Scene", "load_scene",
           "pipelines", "render", "shader_library_names", "__version__"]


class Pipeline:
    """A pipeline written in Python (the SRP's C# role): render(frame) records passes, draws and
    blits into `frame` (an ontile.Frame) with C++ shaders from frame.shaders(name), then calls
    frame.submit(surface) or frame.submit_graph(graph, resource). `name` is what the report's
    run.pipeline says."""

    name = ""
    description = ""

    def render(self, frame):
        raise NotImplementedError(f"{type(self).__name__}.render(frame) records the frame")


class RenderResult:
    """One rendered frame: `image` (NumPy), `report` (dict), `format` (the image's pixel format)."""

    def __init__(self, native):
        self._native = native
        self._report = None

    @property
    def image(self):
        return self._native.image

    @property
    def format(self):
        return self._native.format

    @property
    def report_json(self):
        """The report exactly as `ontile render --report FILE` writes it (text)."""
        return self._native.report_json

    @property
    def frame_times_ms(self):
        """With render(frames=N): the N timed frames' wall-clock times (ms), after one warm-up."""
        return list(self._native.frame_times_ms)

    @property
    def median_ms(self):
        """The timed frames' median (ms), as `ontile render --frames N` prints it; None without frames."""
        times = sorted(self._native.frame_times_ms)
        if not times:
            return None
        n = len(times)
        return times[n // 2] if n % 2 else 0.5 * (times[n // 2 - 1] + times[n // 2])

    @property
    def min_ms(self):
        """The fastest timed frame (ms); None without frames."""
        times = self._native.frame_times_ms
        return min(times) if times else None

    @property
    def report(self):
        if self._report is None:
            self._report = json.loads(self._native.report_json)
        return self._report

    def write_png(self, path):
        """Writes the image as `ontile render --out FILE.png` would: the same bytes."""
        self._native.write_png(str(path))


def pipelines():
    """The registered pipelines' names, sorted (as `ontile pipelines` lists them)."""
    return list(_ontile.pipeline_names())


def _size(size):
    try:
        width, height = (int(v) for v in size)
    except (TypeError, ValueError):
        raise ValueError(f"size: expected (width, height), got {size!r}") from None
    return width, height


def render(scene, pipeline="lambert", size=(1280, 720), camera=None, view=None, yfov_rad=None,
           znear=None, zfar=None, threads=0, options=None, frames=0):
    """Renders `scene` (an ontile.Scene, or a path to load) and returns a RenderResult.

    pipeline: a registered name (ontile.pipelines()) or an ontile.Pipeline object.
    camera: the scene camera's index (default: the first camera, or one framing the scene).
    view: a 4x4 world-to-camera matrix (NumPy, row-major, looking down -Z) replacing the
        camera's placement; yfov_rad, znear and zfar (0: infinite) replace its projection.
    threads: worker threads, 0 for all cores (the bits do not depend on it).
    options: the `ontile render` flags by name with underscores: tile, budget, subpixel_bits,
        arch, afbc, texture_cache_kib, rt_cache_kib, parameter_cache_kib, render_graph,
        gbuffer, lights, tiles (per-tile report), and set={KEY: VALUE} for --set.
    frames: as `ontile render --frames N`: one warm-up render, then N timed ones (0..100); the
        result keeps the last frame and has frame_times_ms, median_ms and min_ms.
    Bad options raise ValueError (ontile.Error), naming the option.
    """
    if not isinstance(frames, int) or isinstance(frames, bool):
        raise ValueError(f"frames: expected a frame count, got {frames!r}")
    if isinstance(scene, str):
        scene = load_scene(scene)
    if isinstance(pipeline, type) and issubclass(pipeline, Pipeline):
        pipeline = pipeline()
    width, height = _size(size)
    if camera is not None and (not isinstance(camera, int) or camera < 0):
        raise ValueError(f"camera: expected a camera index >= 0, got {camera!r}")
    if view is not None:
        import numpy
        view = numpy.asarray(view, dtype=numpy.float64)
    native = _ontile.render(scene, pipeline, width, height, -1 if camera is None else camera, view,
                            yfov_rad, znear, zfar, int(threads), frames, dict(options or {}))
    return RenderResult(native)
