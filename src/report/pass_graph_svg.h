// The frame's pass graph as SVG for the HTML report, in two views: the passes as written (a
// render graph's passes against the resources they write and read, culled passes marked) and the
// native passes as executed (each pass's attachments with load/store actions, transient or in
// memory, and the bytes on every edge to and from external memory).
#pragma once
#include <string>
#include <vector>

#include "context/frame_report.h"
#include "report/pass_capture.h"

namespace ontile {

// Nodes carry class "graph-node", edges "graph-edge" (the page's tests count them).
std::string written_graph_svg(const GraphReport& graph);
// `captured` holds the load/store actions (PassCapture, same order as frame.passes); when its
// size differs from frame.passes the actions shown are derived from the bytes moved.
std::string executed_graph_svg(const FrameReport& frame, const std::vector<CapturedPass>& captured);

}  // namespace ontile
