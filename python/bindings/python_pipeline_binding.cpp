// The recording API of Python pipelines (docs/python.md): ontile.Frame, attachments, render
// graphs, pass builders and recorders, bound to the same C++ context and render-graph calls a
// C++ pipeline makes. Enumerations are spelled as strings ("clear", "store", "d32f", ...).
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "python_frame.h"
#include "util/error.h"

namespace py = pybind11;

namespace ontile::python {
namespace {

PixelFormat format_of(const std::string& name) {
  if (const auto format = parse_pixel_format(name)) return *format;
  throw Error("unknown pixel format '" + name + "' (rgba8, rgba8_srgb, rgb10a2, rg11b10f, rgba16f, rg16f, r32f, "
              "rgba32f, d32f, d24s8, d16, rg16)");
}

LoadAction load_of(const std::string& name) {
  if (name == "clear") return LoadAction::Clear;
  if (name == "load") return LoadAction::Load;
  if (name == "dont_care") return LoadAction::DontCare;
  throw Error("unknown load action '" + name + "' (clear, load, dont_care)");
}

StoreAction store_of(const std::string& name) {
  if (name == "store") return StoreAction::Store;
  if (name == "dont_care") return StoreAction::DontCare;
  throw Error("unknown store action '" + name + "' (store, dont_care)");
}

SortingCriteria sorting_of(const std::string& name) {
  if (name == "common_opaque") return SortingCriteria::CommonOpaque;
  if (name == "common_transparent") return SortingCriteria::CommonTransparent;
  if (name == "none") return SortingCriteria::None;
  throw Error("unknown sorting '" + name + "' (common_opaque, common_transparent, none)");
}

// "opaque", "transparent", "all", or an inclusive (lower, upper) render-queue range.
RenderQueueRange queue_of(const py::object& queue) {
  if (py::isinstance<py::str>(queue)) {
    const std::string name = queue.cast<std::string>();
    if (name == "opaque") return RenderQueueRange::opaque();
    if (name == "transparent") return RenderQueueRange::transparent();
    if (name == "all") return RenderQueueRange::all();
    throw Error("unknown render queue '" + name + "' (opaque, transparent, all, or (lower, upper))");
  }
  const auto range = queue.cast<std::pair<int, int>>();
  return {range.first, range.second};
}

glm::vec4 vec4_of(const std::vector<float>& v) {
  if (v.size() != 4) throw Error("expected 4 values (r, g, b, a), got " + std::to_string(v.size()));
  return {v[0], v[1], v[2], v[3]};
}

DrawingSettings drawing_of(const std::vector<std::string>& light_modes, const std::string& sorting) {
  return {light_modes, sorting_of(sorting)};
}

void bind_values(py::module_& m) {
  py::class_<Surface>(m, "Surface", "A render target owned by the context")
      .def_property_readonly("name", &Surface::name)
      .def_property_readonly("format", [](const Surface& s) { return std::string(format_name(s.format())); })
      .def_property_readonly("width", &Surface::width)
      .def_property_readonly("height", &Surface::height)
      .def_property_readonly("samples", &Surface::samples);

  py::class_<Attachment>(m, "Attachment", "A render pass attachment (context/attachment.h)")
      .def_static("stored", [](const std::string& name, Surface* s) { return Attachment::stored(name, s); },
                  py::arg("name"), py::arg("surface"))
      .def_static("transient", [](const std::string& name, const std::string& format) {
        return Attachment::transient(name, format_of(format)); }, py::arg("name"), py::arg("format"))
      .def("clear", [](const Attachment& a, const std::vector<float>& v) { return a.clear(vec4_of(v)); })
      .def("clear_depth", &Attachment::clear_depth)
      .def("load", &Attachment::load)
      .def("store", &Attachment::store)
      .def("discard", &Attachment::discard)
      .def("resolve_into", &Attachment::resolve_into)
      .def("store_and_resolve_into", &Attachment::store_and_resolve_into);

  py::class_<CullingResults>(m, "CullingResults", "The visible renderers of a frame.cull(shaders)")
      .def_property_readonly("visible_count", [](const CullingResults& c) { return c.visible.size(); });
  py::class_<CameraMatrices>(m, "CameraMatrices", "The frame camera's matrices at the frame's aspect");
  py::class_<RenderMaterial>(m, "Material", "A material of a shader library (blits)")
      .def_readonly("name", &RenderMaterial::name);
  py::class_<ShaderLibrary>(m, "ShaderLibrary", "C++ shaders looked up by name (frame.shaders(name))")
      .def("material", &ShaderLibrary::material, py::return_value_policy::reference_internal)
      .def_property_readonly("background_color", [](const ShaderLibrary& l) {
        const glm::vec4 c = l.background_color();
        return std::vector<float>{c.x, c.y, c.z, c.w};
      });
  py::class_<GraphResource>(m, "GraphResource").def_readonly("index", &GraphResource::index);
}

void bind_graph(py::module_& m) {
  py::class_<GraphPassRecorder>(m, "GraphPassRecorder", "What a graph pass records its draws into")
      .def("draw_renderers", [](GraphPassRecorder& r, const CullingResults& culling,
                                const std::vector<std::string>& light_modes, const std::string& sorting,
                                const py::object& queue) {
        r.draw_renderers(culling, drawing_of(light_modes, sorting), {queue_of(queue)});
      }, py::arg("culling"), py::arg("light_modes"), py::arg("sorting") = "common_opaque", py::arg("queue") = "all")
      .def("draw_skybox", &GraphPassRecorder::draw_skybox, py::arg("matrices"))
      .def("on_tile", &GraphPassRecorder::on_tile)
      .def("set_global_texture", [](GraphPassRecorder& r, const std::string& name, GraphResource resource) {
        r.set_global_texture(name, r.texture(resource));
      })
      .def("blit_from", &GraphPassRecorder::blit_from, py::arg("source"), py::arg("material"), py::arg("pass_name"));

  py::class_<GraphPassBuilder>(m, "GraphPassBuilder", "Declares one graph pass; calls chain")
      .def("write_color", [](GraphPassBuilder& b, GraphResource r, const std::string& load, const std::string& store) {
        return b.write_color(r, load_of(load), store_of(store)); })
      .def("write_depth", [](GraphPassBuilder& b, GraphResource r, const std::string& load, const std::string& store) {
        return b.write_depth(r, load_of(load), store_of(store)); })
      .def("read_depth", [](GraphPassBuilder& b, GraphResource r, const std::string& load, const std::string& store) {
        return b.read_depth(r, load_of(load), store_of(store)); },
        py::arg("resource"), py::arg("load") = "load", py::arg("store") = "dont_care")
      .def("read_own_pixel", &GraphPassBuilder::read_own_pixel)
      .def("read_texture", &GraphPassBuilder::read_texture)
      .def("record", [](GraphPassBuilder& b, py::function record) {
        // Called back while the graph executes, on the thread that submits (with the GIL).
        return b.record([record](GraphPassRecorder& r) { record(py::cast(&r, py::return_value_policy::reference)); });
      });

  py::class_<RenderGraph>(m, "RenderGraph", "Resources and passes compiled with the --render-graph mode")
      .def("create", [](RenderGraph& g, const std::string& name, const std::string& format, int width_px,
                        int height_px, int samples, const std::vector<float>& clear, bool memoryless) {
        return g.create({name, format_of(format), width_px, height_px, samples, vec4_of(clear), {}, memoryless});
      }, py::arg("name"), py::arg("format"), py::arg("width"), py::arg("height"), py::arg("samples") = 1,
         py::arg("clear") = std::vector<float>{0, 0, 0, 0}, py::arg("memoryless") = false)
      .def("add_pass", &RenderGraph::add_pass, py::keep_alive<0, 1>())
      .def("mark_output", &RenderGraph::mark_output);
}

void bind_frame(py::module_& m) {
  using F = PythonFrame;
  py::class_<F, std::shared_ptr<F>>(m, "Frame", "What a Python pipeline's render(frame) records into")
      .def_property_readonly("pipeline", &F::pipeline)
      .def_property_readonly("width", [](const F& f) { return f.kit().width_px(); })
      .def_property_readonly("height", [](const F& f) { return f.kit().height_px(); })
      .def_property_readonly("matrices", [](const F& f) { return &f.kit().matrices(); },
                             py::return_value_policy::reference_internal)
      .def_property_readonly("options", [](const F& f) { return f.inputs().options.values(); })
      .def("take_option", [](const F& f, const std::string& key, const std::string& fallback) {
        return f.inputs().options.take(key, fallback); })
      .def("reject_unknown_options", [](const F& f) { f.inputs().options.reject_unknown(f.pipeline()); })
      .def("shaders", [](F& f, const std::string& name, const std::map<std::string, std::string>& params) {
        return &f.add_library(make_shader_library(name, params));
      }, py::arg("name"), py::arg("params") = std::map<std::string, std::string>{},
         py::return_value_policy::reference_internal)
      .def("cull", &F::cull, py::return_value_policy::reference_internal)
      .def("set_globals", [](const F& f, const ShaderLibrary& l) { l.set_globals(f.context(), f.kit()); })
      .def("create_target", [](const F& f, const std::string& name, const std::string& format, int samples) {
        return f.kit().create_target(name, format_of(format), samples);
      }, py::arg("name"), py::arg("format"), py::arg("samples") = 1, py::return_value_policy::reference)
      .def("graph", &F::add_graph, py::return_value_policy::reference_internal)
      .def("begin_render_pass", [](const F& f, const std::string& name, const std::vector<Attachment>& attachments,
                                   int depth_index, int samples) {
        f.context().begin_render_pass(name, f.kit().width_px(), f.kit().height_px(), samples,
                                      {attachments.begin(), attachments.end()}, depth_index);
      }, py::arg("name"), py::arg("attachments"), py::arg("depth_index") = -1, py::arg("samples") = 1)
      .def("begin_subpass", [](const F& f, std::vector<int> colors, std::vector<int> inputs, bool depth_read_only) {
        f.context().begin_subpass(std::move(colors), std::move(inputs), depth_read_only);
      }, py::arg("colors"), py::arg("inputs") = std::vector<int>{}, py::arg("depth_read_only") = false)
      .def("draw_renderers", [](const F& f, const CullingResults& culling, const std::vector<std::string>& light_modes,
                                const std::string& sorting, const py::object& queue) {
        f.context().draw_renderers(culling, drawing_of(light_modes, sorting), {queue_of(queue)});
      }, py::arg("culling"), py::arg("light_modes"), py::arg("sorting") = "common_opaque", py::arg("queue") = "all")
      .def("draw_skybox", [](const F& f) { f.context().draw_skybox(f.kit().matrices()); })
      .def("end_subpass", [](const F& f) { f.context().end_subpass(); })
      .def("end_render_pass", [](const F& f) { f.context().end_render_pass(); })
      .def("set_global_texture", [](const F& f, const std::string& name, Surface* surface) {
        f.context().set_global_texture(name, {nullptr, RenderTargetRef::of(surface), {}});
      })
      .def("blit", [](const F& f, Surface* source, Surface* destination, const RenderMaterial& material,
                      const std::string& pass_name) {
        f.context().blit(RenderTargetRef::of(source), RenderTargetRef::of(destination), &material, pass_name);
      }, py::arg("source"), py::arg("destination"), py::arg("material"), py::arg("pass_name"))
      .def("submit", [](F& f, Surface* shown) { f.set_outputs(f.kit().submit(shown)); }, py::arg("shown"))
      .def("submit_graph", [](F& f, RenderGraph& graph, GraphResource shown) {
        f.set_outputs(f.kit().submit(graph, shown));
      }, py::arg("graph"), py::arg("shown"));
}

}  // namespace

void bind_python_pipelines(py::module_& m) {
  bind_values(m);
  bind_graph(m);
  bind_frame(m);
  m.def("shader_library_names", &shader_library_names);
}

}  // namespace ontile::python
