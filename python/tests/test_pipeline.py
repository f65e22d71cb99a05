"""Pipelines written in Python record through the same context and render-graph API as C++
ones and shade with the same C++ functors: the ports in python/examples/ give the C++
pipelines' images and reports bit for bit; misuse raises Python exceptions."""
import json
import os
import sys
import unittest

from ontile_test_env import DEMO, SOURCE_DIR, needs_module, ontile, output_dir, without_timing

sys.path.insert(0, os.path.join(SOURCE_DIR, "python", "examples"))
if ontile is not None:
    from cartoon_example import CartoonHullPipeline, CartoonPipeline
    from graph_example import GraphExamplePipeline

SIZE = (160, 90)


@needs_module
class PythonPipelinesEqualCpp(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scene = ontile.load_scene(DEMO)

    def assertSameFrame(self, python_pipeline, cpp_name, options):
        python = ontile.render(self.scene, pipeline=python_pipeline, size=SIZE, options=options)
        cpp = ontile.render(self.scene, pipeline=cpp_name, size=SIZE, options=options)
        self.assertEqual(python.format, cpp.format)
        self.assertEqual(python.image.tobytes(), cpp.image.tobytes(), f"{cpp_name} {options}: images differ")
        self.assertEqual(json.dumps(without_timing(python.report), indent=2),
                         json.dumps(without_timing(cpp.report), indent=2))
        return python

    def test_graph_example_in_every_render_graph_mode(self):
        for mode in ("off", "cull", "merge"):
            with self.subTest(mode=mode):
                result = self.assertSameFrame(GraphExamplePipeline(), "graph-example", {"render_graph": mode})
                if mode == "merge":
                    self.assertIn("graph", result.report)

    def test_cartoon_with_explicit_passes_and_a_blit(self):
        self.assertSameFrame(CartoonPipeline(), "cartoon", {})
        self.assertSameFrame(CartoonPipeline(), "cartoon", {"set": {"normals": "rgba16f"}, "tile": 8})

    def test_cartoon_hull_with_a_transient_attachment(self):
        self.assertSameFrame(CartoonHullPipeline(), "cartoon-hull", {"arch": "imr"})


class FloatTarget(ontile.Pipeline if ontile else object):
    """Lit forward shading into a half-float colour target: the image comes back as float32."""
    name = "float-target"

    def render(self, frame):
        lit = frame.shaders("lit")
        culling = frame.cull(lit)
        frame.set_globals(lit)
        color = frame.create_target("color", "rgba16f")
        frame.begin_render_pass("forward", [ontile.Attachment.stored("color", color).clear(lit.background_color),
                                            ontile.Attachment.transient("depth", "d32f").clear_depth(1.0)],
                                depth_index=1)
        frame.begin_subpass([0])
        frame.draw_renderers(culling, ["ForwardLit"], "common_opaque", "opaque")
        frame.end_subpass()
        frame.end_render_pass()
        frame.submit(color)


class NoSubmit(ontile.Pipeline if ontile else object):
    name = "no-submit"

    def render(self, frame):
        frame.cull(frame.shaders("lit"))


class Raises(ontile.Pipeline if ontile else object):
    name = "raises"

    def render(self, frame):
        raise KeyError("recorded nothing")


class KeepsFrame(ontile.Pipeline if ontile else object):
    name = "keeps-frame"
    kept = None

    def render(self, frame):
        KeepsFrame.kept = frame
        frame.submit(frame.create_target("color", "rgba8_srgb"))


class BadNames(ontile.Pipeline if ontile else object):
    name = "bad-names"

    def __init__(self, what):
        self.what = what

    def render(self, frame):
        if self.what == "library":
            frame.shaders("phong")
        elif self.what == "format":
            frame.create_target("color", "rgb8")
        elif self.what == "load":
            graph = frame.graph()
            color = graph.create("color", "rgba8", frame.width, frame.height)
            graph.add_pass("p").write_color(color, "keep", "store")
        elif self.what == "material":
            frame.shaders("lit").material("edges")


@needs_module
class MisuseRaises(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scene = ontile.load_scene(DEMO)

    def render(self, pipeline, **kwargs):
        return ontile.render(self.scene, pipeline=pipeline, size=(16, 16), **kwargs)

    def test_float_target_gives_float32_and_no_png(self):
        result = self.render(FloatTarget())
        self.assertEqual(result.format, "rgba16f")
        self.assertEqual((result.image.shape, str(result.image.dtype)), ((16, 16, 4), "float32"))
        background = [round(float(v), 3) for v in result.image[0, 0]]
        self.assertEqual(background, [0.05, 0.05, 0.08, 1.0])  # the Lit background, as half floats
        self.assertGreater(len({tuple(p) for p in result.image.reshape(-1, 4).tolist()}), 10)
        with self.assertRaisesRegex(ValueError, "PNG needs an 8-bit target"):
            result.write_png(os.path.join(output_dir("pipeline"), "float.png"))

    def test_render_without_submit(self):
        with self.assertRaisesRegex(ValueError, "without frame.submit"):
            self.render(NoSubmit())

    def test_python_exception_passes_through(self):
        with self.assertRaisesRegex(KeyError, "recorded nothing"):
            self.render(Raises())

    def test_frame_is_closed_after_render(self):
        self.render(KeepsFrame())
        with self.assertRaisesRegex(ValueError, "closed"):
            KeepsFrame.kept.create_target("late", "rgba8")

    def test_unknown_names(self):
        for what, message in (("library", "unknown shader library 'phong'"), ("format", "unknown pixel format 'rgb8'"),
                              ("load", "unknown load action 'keep'"), ("material", "has no material 'edges'")):
            with self.subTest(what=what), self.assertRaisesRegex(ValueError, message):
                self.render(BadNames(what))

    def test_unknown_set_option_reaches_the_python_pipeline(self):
        with self.assertRaisesRegex(ValueError, "has no option 'msaa'"):
            self.render(GraphExamplePipeline(), options={"set": {"msaa": 4}})


if __name__ == "__main__":
    unittest.main()
