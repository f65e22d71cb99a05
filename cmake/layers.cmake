# One static library per layer of the data flow (developers' guide: scene -> context -> tiler ->
# raster -> shaders), each seeing only its own headers and those of the layers it links. A
# layer's folders are exposed through a private include tree of symlinks under the build folder
# (build/layers/<layer>/<folder> -> src/<folder>), so `#include "context/..."` inside src/raster
# fails to compile: a wrong-way include is a build error, not a review comment.

set(ONTILE_LAYER_ROOT ${PROJECT_BINARY_DIR}/layers)

# ontile_layer(NAME FOLDERS f... [PUBLIC_DEPS t...] [PRIVATE_DEPS t...])
# Builds ontile_<NAME> from src/<f>/**.cpp for every folder f and publishes the folders' headers
# (as "<f>/...") to the layers that link it.
function(ontile_layer name)
  cmake_parse_arguments(LAYER "" "" "FOLDERS;PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  set(tree ${ONTILE_LAYER_ROOT}/${name})
  file(MAKE_DIRECTORY ${tree})
  set(sources "")
  foreach(folder IN LISTS LAYER_FOLDERS)
    if(NOT EXISTS ${tree}/${folder})
      file(CREATE_LINK ${PROJECT_SOURCE_DIR}/src/${folder} ${tree}/${folder} SYMBOLIC)
    endif()
    file(GLOB_RECURSE folder_sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/${folder}/*.cpp)
    list(APPEND sources ${folder_sources})
  endforeach()
  add_library(ontile_${name} STATIC ${sources})
  target_include_directories(ontile_${name} PUBLIC $<BUILD_INTERFACE:${tree}>)
  target_link_libraries(ontile_${name} PUBLIC ${LAYER_PUBLIC_DEPS} PRIVATE ${LAYER_PRIVATE_DEPS})
endfunction()

ontile_layer(util FOLDERS util PUBLIC_DEPS glm::glm TBB::tbb nlohmann_json::nlohmann_json)
target_compile_definitions(ontile_util PUBLIC GLM_FORCE_XYZW_ONLY GLM_ENABLE_EXPERIMENTAL
  ONTILE_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
ontile_layer(raster FOLDERS raster PUBLIC_DEPS ontile_util PRIVATE_DEPS hwy::hwy)
ontile_layer(io FOLDERS io PUBLIC_DEPS ontile_raster PRIVATE_DEPS OpenImageIO::OpenImageIO)
ontile_layer(scene FOLDERS scene PUBLIC_DEPS ontile_raster
  PRIVATE_DEPS TinyGLTF::TinyGLTF ${STB_LIBRARY})
ontile_layer(shaders FOLDERS shaders_cpp PUBLIC_DEPS ontile_scene ontile_io PRIVATE_DEPS hwy::hwy)
# The external-memory models that price what the tiler moves (src/memory/: the MemoryModel seam,
# TBDR and IMR models, the shared set-associative cache, AFBC, transaction elimination).
ontile_layer(memory FOLDERS memory PUBLIC_DEPS ontile_raster PRIVATE_DEPS hwy::hwy ZLIB::ZLIB)
ontile_layer(tiler FOLDERS tiler PUBLIC_DEPS ontile_raster ontile_memory PRIVATE_DEPS hwy::hwy)
# The context executes frames on the tiler and owns the built-in full-screen functors (blits,
# clears, the sky), but its headers show neither the shader library nor Highway to pipelines.
ontile_layer(context FOLDERS context PUBLIC_DEPS ontile_tiler ontile_scene PRIVATE_DEPS ontile_shaders)
ontile_layer(pipelines FOLDERS pipelines PUBLIC_DEPS ontile_context ontile_shaders)
# Pipelines register themselves from static objects (pipelines/kit/pipeline.h): every member of
# the archive must be linked, even though nothing refers to it by name.
ontile_layer(tools FOLDERS aov analysis charts golden reference report studies
  PUBLIC_DEPS "$<LINK_LIBRARY:WHOLE_ARCHIVE,ontile_pipelines>" PRIVATE_DEPS embree)

# Everything, for the CLI, the tests, the benchmarks and the fuzzers.
add_library(ontile_core INTERFACE)
target_link_libraries(ontile_core INTERFACE ontile_tools)
