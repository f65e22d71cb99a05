# One static library per layer of the data flow (developers' guide: scene -> context -> tiler ->
# raster -> shaders), each seeing only its own headers and those of the layers it links. A
# layer's folders are exposed through a private include tree of symlinks under the build folder
# (build/layers/<layer>/<folder> -> src/<folder>), so `#include "context/..."` inside src/raster
# fails to compile: a wrong-way include is a build error, not a review comment.

set(ONTILE_LAYER_ROOT ${PROJECT_BINARY_DIR}/layers)

# ontile_layer(NAME FOLDERS f... [PUBLIC_DEPS t...] [PRIVATE_DEPS t...])
# Builds ontile_<NAME> from src/<f>/**.cpp for every folder f and publishes the folders' headers
# (as "<f>/...") to the layers that link it. Installed (cmake/package.cmake), every layer's
# headers go to include/ontile/<f>/ and the library is exported as ontile::<NAME>.
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
  target_include_directories(ontile_${name} PUBLIC $<BUILD_INTERFACE:${tree}>
                                                   $<INSTALL_INTERFACE:include/ontile>)
  target_link_libraries(ontile_${name} PUBLIC ${LAYER_PUBLIC_DEPS} PRIVATE ${LAYER_PRIVATE_DEPS})
  set_target_properties(ontile_${name} PROPERTIES EXPORT_NAME ${name})
  set_property(GLOBAL APPEND PROPERTY ONTILE_LAYER_TARGETS ontile_${name})
  set_property(GLOBAL APPEND PROPERTY ONTILE_LAYER_FOLDERS ${LAYER_FOLDERS})
endfunction()

# libstb (Debian's stb_image and stb_image_write, one shared library without a CMake config) as
# an imported target, so the exported scene layer names ontile::stb rather than a path;
# ontileConfig.cmake defines the same target for consumers.
add_library(ontile::stb UNKNOWN IMPORTED)
set_target_properties(ontile::stb PROPERTIES IMPORTED_LOCATION ${STB_LIBRARY})

ontile_layer(util FOLDERS util PUBLIC_DEPS glm::glm TBB::tbb nlohmann_json::nlohmann_json)
target_compile_definitions(ontile_util PUBLIC GLM_FORCE_XYZW_ONLY GLM_ENABLE_EXPERIMENTAL)
ontile_layer(raster FOLDERS raster PUBLIC_DEPS ontile_util PRIVATE_DEPS hwy::hwy)
ontile_layer(io FOLDERS io PUBLIC_DEPS ontile_raster PRIVATE_DEPS OpenImageIO::OpenImageIO)
ontile_layer(scene FOLDERS scene PUBLIC_DEPS ontile_raster
  PRIVATE_DEPS TinyGLTF::TinyGLTF ontile::stb)
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
# (The installed form names the exported target: CMake does not rename targets inside
# $<LINK_LIBRARY>.)
ontile_layer(tools FOLDERS aov analysis charts golden reference report studies
  PUBLIC_DEPS "$<BUILD_INTERFACE:$<LINK_LIBRARY:WHOLE_ARCHIVE,ontile_pipelines>>"
              "$<INSTALL_INTERFACE:$<LINK_LIBRARY:WHOLE_ARCHIVE,ontile::pipelines>>"
  PRIVATE_DEPS embree)

# Everything, for the CLI, the tests, the benchmarks, the fuzzers and other projects (exported as
# ontile::ontile; ontile::ontile is also its name for a parent project's add_subdirectory). The
# installed target carries the determinism flags: headers hold inline arithmetic (shader
# functors, pixel formats) that a consumer's compiler must not contract into fused multiply-adds
# either. (In this build add_compile_options already gives them to every target; a parent project
# using add_subdirectory sets its own flags.)
add_library(ontile_core INTERFACE)
target_link_libraries(ontile_core INTERFACE ontile_tools)
target_compile_features(ontile_core INTERFACE cxx_std_20)
target_compile_options(ontile_core INTERFACE $<INSTALL_INTERFACE:-ffp-contract=off -fno-fast-math>)
set_target_properties(ontile_core PROPERTIES EXPORT_NAME ontile)
add_library(ontile::ontile ALIAS ontile_core)
