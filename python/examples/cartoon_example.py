"""`cartoon` and `cartoon-hull` written in Python with explicit render passes (the Vulkan-style
half of the context API, beside graph_example.py's render graph): an MRT G-buffer pass, then the
Sobel edge blit; and one pass with a stored colour and a transient depth attachment drawing
inverted-hull outlines. Same images and reports as the C++ pipelines (python/tests/test_pipeline.py).

    PYTHONPATH=build/python python3 python/examples/cartoon_example.py scenes/demo.glb out/cartoon.png
"""
import sys

import ontile

NO_CLEAR = [0.0, 0.0, 0.0, 0.0]


class CartoonPipeline(ontile.Pipeline):
    name = "cartoon"
    description = "toon G-buffer in one MRT pass, then Sobel edges (src/pipelines/cartoon)"

    def render(self, frame):
        normals_option = frame.take_option("normals", "rgb10a2")
        frame.reject_unknown_options()
        toon = frame.shaders("toon", {"normals": normals_option})
        culling = frame.cull(toon)
        frame.set_globals(toon)
        color = frame.create_target("color", "rgba8_srgb")
        normals = frame.create_target("normals", normals_option)
        border = frame.create_target("border", "rgba8")
        depth = frame.create_target("depth", "d32f")
        final = frame.create_target("final", "rgba8_srgb")

        frame.begin_render_pass("toon MRT", [
            ontile.Attachment.stored("color", color).clear(NO_CLEAR),
            ontile.Attachment.stored("normals", normals).clear(NO_CLEAR),
            ontile.Attachment.stored("border", border).clear(NO_CLEAR),
            ontile.Attachment.stored("depth", depth).clear_depth(1.0)], depth_index=3)
        frame.begin_subpass([0, 1, 2])
        frame.draw_renderers(culling, ["ToonMRT"], "common_opaque", "all")
        frame.draw_skybox()
        frame.end_subpass()
        frame.end_render_pass()

        # Screen-space edges: Sobel on depth and normals, coloured by the border buffer.
        frame.set_global_texture("_DepthTex", depth)
        frame.set_global_texture("_NormalTex", normals)
        frame.set_global_texture("_BorderTex", border)
        frame.blit(color, final, toon.material("edges"), "Edges")
        frame.submit(final)


class CartoonHullPipeline(ontile.Pipeline):
    name = "cartoon-hull"
    description = "toon environment shading and inverted-hull outlines in one pass"

    def render(self, frame):
        frame.reject_unknown_options()
        toon = frame.shaders("toon-env")
        culling = frame.cull(toon)
        frame.set_globals(toon)
        color = frame.create_target("color", "rgba8_srgb")
        frame.begin_render_pass("toon forward + hull outlines", [
            ontile.Attachment.stored("color", color).clear(NO_CLEAR),
            ontile.Attachment.transient("depth", "d32f").clear_depth(1.0)], depth_index=1)
        frame.begin_subpass([0])
        frame.draw_renderers(culling, ["ToonColor"])
        frame.draw_skybox()
        # Inverted hulls after the shaded surfaces: only the rim around each object survives.
        frame.draw_renderers(culling, ["ToonOutline"])
        frame.end_subpass()
        frame.end_render_pass()
        frame.submit(color)


def main(argv):
    if len(argv) != 3:
        print("usage: cartoon_example.py SCENE.glb OUT.png", file=sys.stderr)
        return 2
    result = ontile.render(argv[1], pipeline=CartoonPipeline(), size=(640, 360))
    result.write_png(argv[2])
    print(f"wrote {argv[2]}: {result.report['frame']['bytes_read']} bytes read")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
