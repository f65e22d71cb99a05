// A small SVG 1.1 writer for the charts ontile draws (sweep plot, heatmap legends, pass graphs):
// shapes, text and groups with escaped attributes and numbers printed the same on every run.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace ontile {

struct Rgb {
  uint8_t r = 0, g = 0, b = 0;
  std::string hex() const;  // "#rrggbb"
};

// How a shape is painted; an empty fill or stroke means "none".
struct SvgStyle {
  std::string fill, stroke;
  double stroke_width = 1.0;
  std::string dash;       // stroke-dasharray, e.g. "4 3"
  std::string css_class;  // class attribute, for the page's stylesheet and tests

  static SvgStyle filled(std::string fill, std::string css_class = "") {
    SvgStyle s;
    s.fill = std::move(fill);
    s.css_class = std::move(css_class);
    return s;
  }
  static SvgStyle stroked(std::string stroke, double width = 1.0, std::string dash = "", std::string css_class = "") {
    SvgStyle s;
    s.stroke = std::move(stroke);
    s.stroke_width = width;
    s.dash = std::move(dash);
    s.css_class = std::move(css_class);
    return s;
  }
};

enum class TextAnchor { Start, Middle, End };

struct SvgText {
  double size_px = 12.0;
  TextAnchor anchor = TextAnchor::Start;
  std::string fill = "#222";
  bool bold = false;
  bool monospace = false;
  double rotate_deg = 0.0;  // about the text's anchor point (-90: reads upwards)
};

// Numbers with at most two decimals, trailing zeros dropped ("12", "3.5", "-0.25").
std::string svg_number(double value);
// Text and attribute values with &, <, >, " and ' escaped.
std::string xml_escape(const std::string& text);

class SvgWriter {
 public:
  // An <svg> of width x height user units (pixels), with a viewBox of the same size.
  SvgWriter(double width_px, double height_px, const std::string& css_class = "");

  void rect(double x, double y, double width, double height, const SvgStyle& style, double corner_radius = 0.0);
  void line(double x0, double y0, double x1, double y1, const SvgStyle& style);
  void polyline(const std::vector<std::pair<double, double>>& points, const SvgStyle& style);
  void circle(double cx, double cy, double radius, const SvgStyle& style);
  // A straight arrow from (x0, y0) to (x1, y1) with its head at the end.
  void arrow(double x0, double y0, double x1, double y1, const SvgStyle& style);
  void text(double x, double y, const std::string& text, const SvgText& style = {});
  // An image (e.g. a data: URI) stretched over the rectangle without smoothing: one image pixel
  // per heatmap cell stays a sharp square.
  void image(double x, double y, double width, double height, const std::string& href);
  // A horizontal linear gradient named `id` through the colours (evenly spaced), for legends.
  void linear_gradient(const std::string& id, const std::vector<Rgb>& colors);
  // A hover tooltip for the next element: <g><title>...</title> ... </g>.
  void begin_group(const std::string& tooltip = "", const std::string& css_class = "");
  void end_group();

  // The document: "<svg ...>...</svg>\n". Inline in HTML it needs no namespace; a standalone
  // .svg file gets the XML declaration and xmlns. Throws Error if a group is still open.
  std::string str(bool standalone_file = false) const;

 private:
  std::string style_attributes(const SvgStyle& style) const;
  double width_px_, height_px_;
  std::string css_class_, body_, defs_;
  int open_groups_ = 0;
};

}  // namespace ontile
