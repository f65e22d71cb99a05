// ontile.load_scene, ontile.pipelines and ontile.render for the registered (C++) pipelines:
// the same render_frame call and report JSON as `ontile render`, with the image handed to
// NumPy. ontile::Error becomes ontile.Error, a ValueError.
#include <chrono>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <glm/gtc/matrix_inverse.hpp>

#include "bindings.h"
#include "io/image_io.h"
#include "python_frame.h"
#include "render_options.h"
#include "scene/gltf_loader.h"
#include "util/error.h"
#include "util/heap_tuning.h"

namespace py = pybind11;

namespace ontile::python {
namespace {

LoadedScene load_scene(const std::string& path, bool allow_outside_files, const std::string& texture_compression) {
  GltfLoadOptions options;  // as the CLI loads scenes (apps/ontile/cli_scene.cpp)
  options.allow_uris_outside_scene_folder = allow_outside_files;
  const std::optional<TextureCompression> compression = parse_texture_compression(texture_compression);
  if (!compression) {
    throw Error("texture_compression: '" + texture_compression + "' not one of none, astc4x4, astc8x8, etc2");
  }
  options.texture_compression = *compression;
  LoadedScene loaded;
  loaded.path = path;
  loaded.texture_compression = *compression;
  {
    py::gil_scoped_release release;
    loaded.scene = std::make_shared<const Scene>(load_gltf(path, options));
  }
  return loaded;
}

// 8-bit targets as uint8 bytes (as the PNG holds them); every other format decoded to float32.
py::array image_array(const Surface& color) {
  const py::ssize_t h = color.height(), w = color.width();
  if (color.samples() == 1 &&
      (color.format() == PixelFormat::RGBA8_SRGB || color.format() == PixelFormat::RGBA8_UNORM)) {
    py::array_t<uint8_t> image({h, w, py::ssize_t{4}});
    std::copy(color.bytes().begin(), color.bytes().end(), image.mutable_data());
    return image;
  }
  py::array_t<float> image({h, w, py::ssize_t{4}});
  float* out = image.mutable_data();
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const glm::vec4 v = color.read(x, y);
      *out++ = v.x, *out++ = v.y, *out++ = v.z, *out++ = v.w;
    }
  }
  return image;
}

glm::dmat4 matrix_from_numpy(const py::array_t<double, py::array::c_style | py::array::forcecast>& m) {
  if (m.ndim() != 2 || m.shape(0) != 4 || m.shape(1) != 4) throw Error("view: expected a 4x4 matrix");
  glm::dmat4 out;
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col < 4; ++col) out[col][row] = m.at(row, col);  // GLM is column-major
  }
  return out;
}

// `pipeline`: a registered pipeline's name, or a Python pipeline object (python_frame.h).
std::unique_ptr<RenderResult> render_any(const LoadedScene& scene, const py::object& pipeline, int width_px,
                                                int height_px, int camera_index, std::optional<py::array> view,
                                                std::optional<float> yfov_rad, std::optional<float> znear,
                                                std::optional<float> zfar, int threads, int frames,
                                                const py::dict& options) {
  if (frames < 0 || frames > 100) throw Error("frames: " + std::to_string(frames) + " not in 0..100");
  std::unique_ptr<Pipeline> python_pipeline;
  ParsedOptions parsed;
  if (py::isinstance<py::str>(pipeline)) {
    parsed.settings.pipeline = pipeline.cast<std::string>();
  } else {
    python_pipeline = make_python_pipeline(pipeline);
    parsed.settings.pipeline = python_pipeline->name();
  }
  parsed.settings.width_px = width_px;
  parsed.settings.height_px = height_px;
  parsed.settings.camera_index = camera_index;
  if (threads < 0 || threads > 1024) throw Error("threads: " + std::to_string(threads) + " not in 0..1024");
  parsed.settings.context.threads = threads;
  parsed = parse_render_options(options, parsed);
  CameraOverride camera{false, glm::dmat4(1.0), yfov_rad, znear, zfar};
  if (view) {
    camera.has_view = true;
    camera.view = matrix_from_numpy(*view);
  }
  return render_with(scene, parsed.settings, camera, parsed.tile_report, parsed.gpu, python_pipeline.get(), frames);
}

}  // namespace

std::unique_ptr<RenderResult> render_with(const LoadedScene& scene, const RenderSettings& settings,
                                          const CameraOverride& camera, bool tile_report, const std::string& gpu,
                                          Pipeline* pipeline, int frames) {
  auto result = std::make_unique<RenderResult>();
  result->scene = scene.scene;
  std::unique_ptr<Pipeline> registered;
  if (!pipeline) {
    registered = make_pipeline(settings.pipeline);
    pipeline = registered.get();
  }
  // Steady-state frame times: the frames reuse the heap instead of fresh pages (heap_tuning.h).
  if (frames > 0) keep_freed_memory_in_the_heap();
  for (int frame_index = 0; frame_index <= frames; ++frame_index) {
    const auto start = std::chrono::steady_clock::now();
    RenderSettings frame_settings = settings;
    frame_settings.frame_index = frame_index;
    FrameInputs inputs = frame_inputs(*scene.scene, frame_settings);
    if (camera.has_view) inputs.camera.world = glm::inverse(camera.view);  // camera-to-world
    if (camera.yfov_rad) inputs.camera.yfov_rad = *camera.yfov_rad;
    if (camera.znear) inputs.camera.znear = *camera.znear;
    if (camera.zfar) inputs.camera.zfar = *camera.zfar;
    RenderedFrame frame;
    frame.camera = inputs.camera;
    frame.context = std::make_unique<RenderContext>(settings.context);
    if (registered) {
      // C++ from here to the end of the frame: other Python threads may run meanwhile.
      py::gil_scoped_release release;
      frame.outputs = pipeline->render(*frame.context, inputs);
    } else {
      frame.outputs = pipeline->render(*frame.context, inputs);
    }
    if (!frame.outputs.color) throw Error("pipeline '" + settings.pipeline + "' returned no image");
    if (frame_index > 0) {
      result->frame_times_ms.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    result->frame = std::move(frame);
  }
  const std::optional<int> timed = frames > 0 ? std::optional<int>(frames) : std::nullopt;
  const RenderRun run{scene.path, settings, "", timed, tile_report, gpu, scene.texture_compression};
  result->report_json = render_report_json(result->frame.outputs.report, run).dump(2) + "\n";
  return result;
}

void bind_render(py::module_& m) {
  py::register_exception<Error>(m, "Error", PyExc_ValueError);

  py::class_<LoadedScene>(m, "Scene", "A glTF scene loaded once, rendered any number of times")
      .def_readonly("path", &LoadedScene::path)
      .def_property_readonly("camera_count", [](const LoadedScene& s) { return s.scene->cameras.size(); })
      .def_property_readonly("camera_names", [](const LoadedScene& s) {
        std::vector<std::string> names;
        for (const Camera& c : s.scene->cameras) names.push_back(c.name);
        return names;
      })
      .def("camera_to_world", [](const LoadedScene& s, int index) {
        const glm::dmat4 world = select_camera(*s.scene, index).world;
        py::array_t<double> m({4, 4});
        for (int row = 0; row < 4; ++row) {
          for (int col = 0; col < 4; ++col) m.mutable_at(row, col) = world[col][row];
        }
        return m;
      }, py::arg("index"), "Camera `index`'s camera-to-world matrix (4x4, row-major); view = its inverse")
      .def_property_readonly("triangle_count", [](const LoadedScene& s) { return s.scene->drawn_triangle_count(); })
      .def("__repr__", [](const LoadedScene& s) { return "<ontile.Scene '" + s.path + "'>"; });
  m.def("load_scene", &load_scene, py::arg("path"), py::arg("allow_outside_files") = false,
        py::arg("texture_compression") = "none",
        "Loads a .gltf or .glb scene with the CLI's loader limits; texture_compression as `ontile render "
        "--texture-compression` (none, astc4x4, astc8x8, etc2); ontile.Error on a bad file");

  m.def("pipeline_names", &pipeline_names, "The registered pipelines, sorted");
  m.def("pipeline_description", [](const std::string& name) { return make_pipeline(name)->description(); });

  py::class_<RenderResult>(m, "RenderResult")
      .def_property_readonly("image", [](const RenderResult& r) { return image_array(*r.frame.outputs.color); })
      .def_property_readonly("format", [](const RenderResult& r) {
        return std::string(format_name(r.frame.outputs.color->format()));
      })
      .def_readonly("report_json", &RenderResult::report_json)
      .def_readonly("frame_times_ms", &RenderResult::frame_times_ms)
      .def("write_png", [](const RenderResult& r, const std::string& path) {
        const Surface& color = *r.frame.outputs.color;
        if (color.format() != PixelFormat::RGBA8_SRGB && color.format() != PixelFormat::RGBA8_UNORM) {
          throw Error(path + ": PNG needs an 8-bit target, the pipeline produced " + format_name(color.format()));
        }
        write_png_rgba8(path, color.width(), color.height(), color.bytes());
      }, py::arg("path"), "Writes the image as `ontile render --out FILE.png` does (the same bytes)");

  m.def("render", &render_any, py::arg("scene"), py::arg("pipeline"), py::arg("width_px"),
        py::arg("height_px"), py::arg("camera"), py::arg("view"), py::arg("yfov_rad"), py::arg("znear"),
        py::arg("zfar"), py::arg("threads"), py::arg("frames"), py::arg("options"));
}

}  // namespace ontile::python

PYBIND11_MODULE(_ontile, m) {
  m.doc() = "ontile's C++ core: scenes, registered pipelines, Python-recorded pipelines";
  m.attr("__version__") = ONTILE_VERSION;
  ontile::python::bind_render(m);
  ontile::python::bind_python_pipelines(m);
}
