"""ontile.render from Python against `ontile render`: the same PNG bytes and the same report
(minus timings) for the same options; bad options raise ValueError."""
import os
import unittest

from ontile_test_env import DEMO, cli_render, needs_module, ontile, output_dir, without_timing

SIZE = (160, 90)


@needs_module
class RenderMatchesCli(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scene = ontile.load_scene(DEMO)
        cls.out = output_dir("render")

    def check_same_as_cli(self, name, pipeline, cli_args, options, threads=0, frames=0):
        cli_png, cli_report = cli_render(self.out, name + "-cli", ["--pipeline", pipeline, "--size", "160x90"] + cli_args)
        result = ontile.render(self.scene, pipeline=pipeline, size=SIZE, threads=threads, options=options, frames=frames)
        self.assertEqual(result.image.shape, (90, 160, 4))
        self.assertEqual(str(result.image.dtype), "uint8")
        png = os.path.join(self.out, name + "-python.png")
        result.write_png(png)
        with open(png, "rb") as f:
            self.assertEqual(f.read(), cli_png, f"{name}: PNG bytes differ from the CLI's")
        self.assertEqual(without_timing(result.report), without_timing(cli_report))
        return result

    def test_cartoon_with_tile_and_threads(self):
        self.check_same_as_cli("cartoon", "cartoon", ["--tile", "32", "--threads", "2"], {"tile": 32}, threads=2)

    def test_lambert_msaa_on_imr(self):
        self.check_same_as_cli("lambert-imr", "lambert", ["--arch", "imr", "--set", "msaa=4", "--rt-cache-kib", "64"],
                               {"arch": "imr", "set": {"msaa": 4}, "rt_cache_kib": 64})

    def test_graph_example_merged_with_afbc_and_tile_report(self):
        self.check_same_as_cli("graph-merge", "graph-example", ["--render-graph", "merge", "--afbc", "on", "--tiles"],
                               {"render_graph": "merge", "afbc": "on", "tiles": True})

    def test_deferred_shorthands(self):
        self.check_same_as_cli("deferred", "deferred-subpass", ["--gbuffer", "vulkan-samples", "--lights", "8"],
                               {"gbuffer": "vulkan-samples", "lights": 8})

    def test_gpu_preset_and_fidelity_options(self):
        result = self.check_same_as_cli("g76", "deferred-subpass",
                                        ["--gpu", "mali-g76", "--varying-precision", "fp16"],
                                        {"varying_precision": "fp16", "gpu": "mali-g76"})
        self.assertEqual(result.report["run"]["gpu"], "mali-g76")
        self.assertEqual(result.report["run"]["transaction_elimination_targets"], "on")
        self.check_same_as_cli("no-idvs", "lambert", ["--gpu", "mali-g71", "--idvs", "off"],
                               {"gpu": "mali-g71", "idvs": False})

    def test_compressed_textures_are_a_scene_option(self):
        cli_png, cli_report = cli_render(self.out, "astc-cli",
                                         ["--pipeline", "lambert", "--size", "160x90", "--texture-compression", "astc8x8"])
        scene = ontile.load_scene(DEMO, texture_compression="astc8x8")
        result = ontile.render(scene, pipeline="lambert", size=SIZE)
        self.assertEqual(without_timing(result.report), without_timing(cli_report))
        self.assertEqual(result.report["run"]["texture_compression"], "astc8x8")

    def test_frames_time_the_renders_after_a_warm_up_as_the_cli(self):
        # The same image and report as `ontile render --frames 3` (run.frames included), and
        # three positive frame times whose median and minimum are the CLI's statistics.
        result = self.check_same_as_cli("frames", "cartoon", ["--frames", "3", "--threads", "2"], {}, threads=2, frames=3)
        times = result.frame_times_ms
        self.assertEqual(len(times), 3)
        self.assertTrue(all(t > 0.0 for t in times), times)
        self.assertEqual(result.min_ms, min(times))
        self.assertEqual(result.median_ms, sorted(times)[1])
        self.assertEqual(result.report["run"]["frames"], 3)
        once = ontile.render(self.scene, pipeline="cartoon", size=SIZE, threads=2)
        self.assertEqual(once.frame_times_ms, [])
        self.assertIsNone(once.median_ms)
        self.assertIsNone(once.report["run"]["frames"])
        self.assertTrue((once.image == result.image).all())

    def test_transaction_elimination_compares_with_the_previous_of_the_frames(self):
        # The Mali preset's CRC history is shared by the frames of one call, as the CLI's.
        result = self.check_same_as_cli("te-frames", "lambert", ["--gpu", "mali-g76", "--frames", "2"],
                                        {"gpu": "mali-g76"}, frames=2)
        self.assertGreater(result.report["passes"][0]["attachments"][0]["te_tiles_eliminated"], 0)

    def test_thread_count_changes_no_bit(self):
        one = ontile.render(self.scene, pipeline="cartoon", size=SIZE, threads=1)
        seven = ontile.render(self.scene, pipeline="cartoon", size=SIZE, threads=7)
        self.assertEqual(one.image.tobytes(), seven.image.tobytes())
        self.assertEqual(one.report["frame"], seven.report["frame"])

    def test_view_matrix_of_the_first_camera_frames_the_same_view(self):
        import numpy
        world = self.scene.camera_to_world(0)
        by_index = ontile.render(self.scene, pipeline="lambert", size=SIZE, camera=0)
        by_view = ontile.render(self.scene, pipeline="lambert", size=SIZE, view=numpy.linalg.inv(world))
        difference = numpy.abs(by_index.image.astype(int) - by_view.image.astype(int))
        self.assertLess(difference.mean(), 0.5)  # the inverse of the inverse, to rounding
        turned = world @ numpy.array([[0, 0, -1, 0], [0, 1, 0, 0], [1, 0, 0, 0], [0, 0, 0, 1]], dtype=float)
        elsewhere = ontile.render(self.scene, pipeline="lambert", size=SIZE, view=numpy.linalg.inv(turned))
        self.assertNotEqual(elsewhere.image.tobytes(), by_index.image.tobytes())

    def test_pipelines_lists_the_registry(self):
        names = ontile.pipelines()
        self.assertEqual(names, sorted(names))
        for name in ("lambert", "cartoon", "graph-example", "universal"):
            self.assertIn(name, names)


@needs_module
class BadInputRaises(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scene = ontile.load_scene(DEMO)

    def assertRaisesValue(self, fragment, **kwargs):
        kwargs.setdefault("size", (16, 16))
        with self.assertRaises(ValueError) as caught:
            ontile.render(self.scene, **kwargs)
        self.assertIn(fragment, str(caught.exception))

    def test_frame_counts_outside_0_to_100(self):
        self.assertRaisesValue("frames: -1 not in 0..100", frames=-1)
        self.assertRaisesValue("frames: 101 not in 0..100", frames=101)
        self.assertRaisesValue("frames: expected a frame count", frames=2.5)

    def test_unknown_option_key(self):
        self.assertRaisesValue("unknown key 'tile_size'", options={"tile_size": 16})

    def test_values_the_cli_refuses(self):
        self.assertRaisesValue("options['tile']", options={"tile": 5})
        self.assertRaisesValue("options['arch']", options={"arch": "gpu"})
        self.assertRaisesValue("options['budget']", options={"budget": 8})
        self.assertRaisesValue("options['render_graph']", options={"render_graph": "all"})
        self.assertRaisesValue("options['tiles']", options={"tiles": 1})
        self.assertRaisesValue("options['gpu']", options={"gpu": "mali-g999"})
        self.assertRaisesValue("needs 16x16 tiles", options={"tile": 32, "gpu": "mali-g76"})
        self.assertRaisesValue("options['varying_precision']", options={"varying_precision": "fp8"})
        with self.assertRaises(ValueError):
            ontile.load_scene(DEMO, texture_compression="bc7")

    def test_pipeline_rejects_unknown_set_option(self):
        self.assertRaisesValue("has no option 'msa'", pipeline="lambert", options={"set": {"msa": 4}})

    def test_unknown_pipeline_size_and_camera(self):
        self.assertRaisesValue("unknown pipeline 'cartoonish'", pipeline="cartoonish")
        self.assertRaisesValue("outside 1..", size=(0, 16))
        self.assertRaisesValue("camera 99 out of range", camera=99)
        with self.assertRaises(ValueError):
            ontile.render(self.scene, size="big")

    def test_bad_scene_file(self):
        with self.assertRaises(ontile.Error) as caught:
            ontile.load_scene(os.path.join(output_dir("render"), "missing.glb"))
        self.assertIsInstance(caught.exception, ValueError)
        self.assertIn("missing.glb", str(caught.exception))


if __name__ == "__main__":
    unittest.main()
