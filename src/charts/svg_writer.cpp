// SVG writer (see svg_writer.h). Numbers go through snprintf with the "C" locale's decimal point
// and a fixed precision, so the same chart gives the same bytes on every run.
#include "charts/svg_writer.h"

#include <cmath>
#include <cstdio>

#include "util/error.h"

namespace ontile {

std::string Rgb::hex() const {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", r, g, b);
  return buf;
}

std::string svg_number(double value) {
  if (!std::isfinite(value)) throw Error("SVG: a coordinate is not finite");
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.2f", std::abs(value) < 0.005 ? 0.0 : value);
  std::string s = buf;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

std::string xml_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

SvgWriter::SvgWriter(double width_px, double height_px, const std::string& css_class)
    : width_px_(width_px), height_px_(height_px), css_class_(css_class) {
  if (!(width_px > 0.0) || !(height_px > 0.0)) throw Error("SVG: the size must be positive");
}

std::string SvgWriter::style_attributes(const SvgStyle& s) const {
  std::string a = " fill=\"" + (s.fill.empty() ? std::string("none") : xml_escape(s.fill)) + "\"";
  if (!s.stroke.empty()) {
    a += " stroke=\"" + xml_escape(s.stroke) + "\" stroke-width=\"" + svg_number(s.stroke_width) + "\"";
    if (!s.dash.empty()) a += " stroke-dasharray=\"" + xml_escape(s.dash) + "\"";
  }
  if (!s.css_class.empty()) a += " class=\"" + xml_escape(s.css_class) + "\"";
  return a;
}

void SvgWriter::rect(double x, double y, double width, double height, const SvgStyle& style, double corner_radius) {
  body_ += "<rect x=\"" + svg_number(x) + "\" y=\"" + svg_number(y) + "\" width=\"" + svg_number(width) +
           "\" height=\"" + svg_number(height) + "\"";
  if (corner_radius > 0.0) body_ += " rx=\"" + svg_number(corner_radius) + "\"";
  body_ += style_attributes(style) + "/>\n";
}

void SvgWriter::line(double x0, double y0, double x1, double y1, const SvgStyle& style) {
  body_ += "<line x1=\"" + svg_number(x0) + "\" y1=\"" + svg_number(y0) + "\" x2=\"" + svg_number(x1) +
           "\" y2=\"" + svg_number(y1) + "\"" + style_attributes(style) + "/>\n";
}

void SvgWriter::polyline(const std::vector<std::pair<double, double>>& points, const SvgStyle& style) {
  body_ += "<polyline points=\"";
  for (size_t i = 0; i < points.size(); ++i) {
    body_ += (i ? " " : "") + svg_number(points[i].first) + "," + svg_number(points[i].second);
  }
  body_ += "\"" + style_attributes(style) + "/>\n";
}

void SvgWriter::circle(double cx, double cy, double radius, const SvgStyle& style) {
  body_ += "<circle cx=\"" + svg_number(cx) + "\" cy=\"" + svg_number(cy) + "\" r=\"" + svg_number(radius) + "\"" +
           style_attributes(style) + "/>\n";
}

void SvgWriter::arrow(double x0, double y0, double x1, double y1, const SvgStyle& style) {
  line(x0, y0, x1, y1, style);
  const double length = std::hypot(x1 - x0, y1 - y0);
  if (length <= 0.0) return;
  const double ux = (x1 - x0) / length, uy = (y1 - y0) / length;
  const double head = 4.0 + 2.0 * style.stroke_width;
  const SvgStyle tip = SvgStyle::filled(style.stroke, style.css_class);
  body_ += "<polygon points=\"" + svg_number(x1) + "," + svg_number(y1) + " " +
           svg_number(x1 - head * ux - head * 0.5 * uy) + "," + svg_number(y1 - head * uy + head * 0.5 * ux) + " " +
           svg_number(x1 - head * ux + head * 0.5 * uy) + "," + svg_number(y1 - head * uy - head * 0.5 * ux) + "\"" +
           style_attributes(tip) + "/>\n";
}

void SvgWriter::text(double x, double y, const std::string& text, const SvgText& style) {
  static const char* const kAnchors[] = {"start", "middle", "end"};
  body_ += "<text x=\"" + svg_number(x) + "\" y=\"" + svg_number(y) + "\" font-size=\"" +
           svg_number(style.size_px) + "\" text-anchor=\"" + kAnchors[static_cast<int>(style.anchor)] +
           "\" fill=\"" + xml_escape(style.fill) + "\" font-family=\"" +
           (style.monospace ? "monospace" : "sans-serif") + "\"";
  if (style.bold) body_ += " font-weight=\"bold\"";
  if (style.rotate_deg != 0.0) {
    body_ += " transform=\"rotate(" + svg_number(style.rotate_deg) + " " + svg_number(x) + " " + svg_number(y) + ")\"";
  }
  body_ += ">" + xml_escape(text) + "</text>\n";
}

void SvgWriter::image(double x, double y, double width, double height, const std::string& href) {
  body_ += "<image x=\"" + svg_number(x) + "\" y=\"" + svg_number(y) + "\" width=\"" + svg_number(width) +
           "\" height=\"" + svg_number(height) +
           "\" preserveAspectRatio=\"none\" style=\"image-rendering:pixelated\" href=\"" + xml_escape(href) + "\"/>\n";
}

void SvgWriter::linear_gradient(const std::string& id, const std::vector<Rgb>& colors) {
  defs_ += "<linearGradient id=\"" + xml_escape(id) + "\" x1=\"0\" y1=\"0\" x2=\"1\" y2=\"0\">";
  for (size_t i = 0; i < colors.size(); ++i) {
    const double offset = colors.size() > 1 ? static_cast<double>(i) / (colors.size() - 1) : 0.0;
    defs_ += "<stop offset=\"" + svg_number(offset) + "\" stop-color=\"" + colors[i].hex() + "\"/>";
  }
  defs_ += "</linearGradient>\n";
}

void SvgWriter::begin_group(const std::string& tooltip, const std::string& css_class) {
  body_ += "<g";
  if (!css_class.empty()) body_ += " class=\"" + xml_escape(css_class) + "\"";
  body_ += ">";
  if (!tooltip.empty()) body_ += "<title>" + xml_escape(tooltip) + "</title>";
  body_ += "\n";
  ++open_groups_;
}

void SvgWriter::end_group() {
  if (open_groups_ == 0) throw Error("SVG: end_group without begin_group");
  body_ += "</g>\n";
  --open_groups_;
}

std::string SvgWriter::str(bool standalone_file) const {
  if (open_groups_ != 0) throw Error("SVG: a group is still open");
  std::string out = standalone_file ? "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\""
                                    : "<svg";
  out += " width=\"" + svg_number(width_px_) + "\" height=\"" +
                    svg_number(height_px_) + "\" viewBox=\"0 0 " + svg_number(width_px_) + " " +
                    svg_number(height_px_) + "\"";
  if (!css_class_.empty()) out += " class=\"" + xml_escape(css_class_) + "\"";
  out += ">\n";
  if (!defs_.empty()) out += "<defs>\n" + defs_ + "</defs>\n";
  return out + body_ + "</svg>\n";
}

}  // namespace ontile
