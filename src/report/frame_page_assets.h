// The HTML report's inline stylesheet and script (frame_page.cpp). The script records errors
// (window.onerror, console.error) and counts the drawn heatmaps and graph elements into
// attributes of <body>, which the browser test reads; it also shows a heatmap tile's value
// under the pointer.
#pragma once

namespace ontile {

// Goes first in <head>, so errors raised while the page loads are recorded too.
inline constexpr const char* kFramePageErrorHook = R"JS(
window.ontileErrors = [];
window.addEventListener('error', function (e) { window.ontileErrors.push(String(e.message)); });
(function () {
  var original = console.error;
  console.error = function () {
    window.ontileErrors.push(Array.prototype.join.call(arguments, ' '));
    return original.apply(console, arguments);
  };
})();
)JS";

inline constexpr const char* kFramePageStyle = R"CSS(
body{font-family:sans-serif;margin:1.5em;color:#222;max-width:1800px}
h1{font-size:1.5em}h2{border-bottom:1px solid #ccc;padding-bottom:4px;margin-top:2em}
table{border-collapse:collapse;margin:0.5em 0 1.5em}td,th{padding:2px 10px;border-bottom:1px solid #e4e4e4;text-align:left}
td.n{text-align:right;font-family:monospace}
.scroll{overflow-x:auto;border:1px solid #eee;padding:6px;background:#fff}
.final img{max-width:100%;border:1px solid #ccc}
.thumbs,.heatmaps{display:flex;flex-wrap:wrap;gap:14px;align-items:flex-start}
figure{margin:0}figcaption{font-size:12px;color:#444;max-width:320px}
figure img{border:1px solid #ccc;display:block}
.transient-box{display:flex;align-items:center;justify-content:center;background:repeating-linear-gradient(45deg,#eef7ee,#eef7ee 8px,#e2f0e2 8px,#e2f0e2 16px);color:#2a6a2a;border:1px dashed #8b8;font-size:12px;text-align:center}
.summary{background:#f6f8fa;border-left:4px solid #89b;padding:6px 10px;max-width:1100px}
.pass{margin-bottom:2.5em}
#tip{position:fixed;pointer-events:none;background:#222;color:#fff;font-size:12px;padding:3px 6px;border-radius:3px;display:none}
)CSS";

inline constexpr const char* kFramePageScript = R"JS(
(function () {
  var tip = document.getElementById('tip');
  document.querySelectorAll('svg.heatmap').forEach(function (svg) {
    var values = svg.getAttribute('data-values').split(',');
    var columns = Number(svg.getAttribute('data-columns'));
    var cell = svg.getAttribute('data-cell').split(',').map(Number);
    svg.addEventListener('mousemove', function (e) {
      var box = svg.getBoundingClientRect();
      var c = Math.floor((e.clientX - box.left) / cell[0]);
      var r = Math.floor((e.clientY - box.top - cell[2]) / cell[1]);
      var i = r * columns + c;
      if (c < 0 || c >= columns || r < 0 || i >= values.length) { tip.style.display = 'none'; return; }
      tip.textContent = 'tile (' + c + ', ' + r + '): ' + values[i];
      tip.style.left = (e.clientX + 12) + 'px';
      tip.style.top = (e.clientY + 12) + 'px';
      tip.style.display = 'block';
    });
    svg.addEventListener('mouseleave', function () { tip.style.display = 'none'; });
  });
  function drawn(selector) {
    var n = 0;
    document.querySelectorAll(selector).forEach(function (e) {
      var box = e.getBoundingClientRect();
      if (box.width > 0 && box.height > 0) ++n;
    });
    return n;
  }
  window.addEventListener('load', function () {
    var body = document.body;
    body.setAttribute('data-heatmaps', drawn('svg.heatmap image'));
    body.setAttribute('data-graph-nodes', drawn('svg.pass-graph .graph-node'));
    body.setAttribute('data-graph-edges', drawn('svg.pass-graph .graph-edge'));
    body.setAttribute('data-images', drawn('img'));
    body.setAttribute('data-errors', window.ontileErrors.length);
    body.setAttribute('data-error-text', window.ontileErrors.join(' | '));
    body.setAttribute('data-ready', '1');
  });
})();
)JS";

}  // namespace ontile
