// sl.render and sl.read_exr (docs/python.md, "Renders"): `scatterlab render` of one material
// without writing, the image as a (height, width, 3) float32 numpy array of linear RGB
// (app/render_command.h renderReport), and the EXR reader the renderer's environment maps use.
#include <algorithm>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "app/render_command.h"
#include "integrator/exr_io.h"
#include "python/src/bindings.h"
#include "python/src/command_options.h"
#include "python/src/json_conversion.h"

namespace scatterlab::python {

namespace py = pybind11;

namespace {

// Rows top to bottom as the film holds them (integrator/image.h), three channels each.
py::array_t<float> imageArray(const Image& image) {
  py::array_t<float> array({size_t(image.height()), size_t(image.width()), size_t(3)});
  float* out = array.mutable_data();
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      std::copy_n(image.pixel(x, y), 3, out + (size_t(y) * image.width() + x) * 3);
  return array;
}

}  // namespace

void bindRender(py::module_& module) {
  module.def(
      "_render",
      [](const std::string& material, const py::dict& keywords, bool progress) {
        RenderCommandOptions options;
        // The options that only shape the written files (a gallery's labels and columns, the
        // PNG's exposure, the EXR's layers) are the command line's.
        CommandOptions command("sl.render", [&](CLI::App& app) { return addRenderCommand(app, options); },
                               {"out", "json", "label", "columns", "exposure", "layers"});
        command.parse(keywords, {material});
        RenderReport report = command.run([&] { return renderReport(options, progress); });
        return py::make_tuple(imageArray(report.result.color), pythonFromJson(report.report));
      },
      py::arg("material"), py::arg("keywords"), py::arg("progress"),
      "`scatterlab render MATERIAL --KEYWORD=VALUE...` as (image (H, W, 3) float32, report dict); see "
      "sl.render");
  module.def(
      "read_exr",
      [](const std::string& path) {
        Image image;
        {
          py::gil_scoped_release release;
          image = readExrRgb(path);
        }
        return imageArray(image);
      },
      py::arg("path"),
      "The R, G and B channels of an EXR file (Y as grey when it has no colour) as a (height, width, 3) "
      "float32 array: what `scatterlab render` writes, read back exactly. ValueError naming the file and "
      "the problem.");
}

}  // namespace scatterlab::python
