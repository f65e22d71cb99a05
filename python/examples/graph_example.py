"""`graph-example` written in Python: the pipeline of docs/context-api.md, a forward renderer as a
render graph (depth prepass, opaques, transparents, and a sky pass whose output nothing reads),
recorded from Python with the Lit shader's C++ functors. It renders the same image and report,
bit for bit, as the C++ `graph-example` (python/tests/test_pipeline.py checks it).

    PYTHONPATH=build/python python3 python/examples/graph_example.py scenes/demo.glb out/graph.png
"""
import sys

import ontile


class GraphExamplePipeline(ontile.Pipeline):
    name = "graph-example"  # the C++ pipeline's name, so that the two reports are byte-equal
    description = "docs/context-api.md's example recorded from Python"

    def render(self, frame):
        frame.reject_unknown_options()  # this pipeline has no --set options
        lit = frame.shaders("lit")
        culling = frame.cull(lit)  # renderers with lit materials, culled
        frame.set_globals(lit)     # the main directional light

        graph = frame.graph()
        w, h = frame.width, frame.height
        color = graph.create("color", "rgba8_srgb", w, h, clear=lit.background_color)
        depth = graph.create("depth", "d32f", w, h, clear=[1.0, 1.0, 1.0, 1.0])
        sky = graph.create("sky", "rgba8", w, h)

        graph.add_pass("depth prepass") \
            .write_depth(depth, "clear", "store") \
            .record(lambda r: r.draw_renderers(culling, ["DepthOnly"], "common_opaque", "opaque"))
        graph.add_pass("opaques") \
            .write_color(color, "clear", "store") \
            .write_depth(depth, "load", "store") \
            .record(lambda r: r.draw_renderers(culling, ["ForwardLit"], "common_opaque", "opaque"))
        graph.add_pass("transparents") \
            .write_color(color, "load", "store") \
            .read_depth(depth, "load", "dont_care") \
            .record(lambda r: r.draw_renderers(culling, ["ForwardLit"], "common_transparent", "transparent"))
        # Nothing reads `sky`: --render-graph cull or merge removes this pass and its bytes.
        graph.add_pass("sky for nobody") \
            .write_color(sky, "clear", "store") \
            .record(lambda r: r.draw_skybox(frame.matrices))

        frame.submit_graph(graph, color)  # marks color as the output, executes, submits


def main(argv):
    if len(argv) != 3:
        print("usage: graph_example.py SCENE.glb OUT.png", file=sys.stderr)
        return 2
    result = ontile.render(argv[1], pipeline=GraphExamplePipeline(), size=(640, 360),
                           options={"render_graph": "merge"})
    result.write_png(argv[2])
    frame = result.report["frame"]
    print(f"wrote {argv[2]}: {frame['bytes_read']} bytes read, {frame['bytes_written']} written")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
