// Everything a pipeline author writes against, in one include (docs/context-api.md): the render
// context and its command buffers, the render graph, attachments, shaders and materials, the
// fragment-functor interface, and the pipeline kit (interface, registration, frame start/end).
// The executor, the tiler and the memory models stay behind the context.
#pragma once

#include "context/attachment.h"
#include "context/camera_matrices.h"
#include "context/command_buffer.h"
#include "context/drawing_settings.h"
#include "context/property_block.h"
#include "context/render_context.h"
#include "context/render_graph.h"
#include "context/scene_renderers.h"
#include "context/shader.h"
#include "pipelines/kit/frame_kit.h"
#include "pipelines/kit/pipeline.h"
#include "raster/shader_interface.h"
