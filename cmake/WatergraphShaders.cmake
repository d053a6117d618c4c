# watergraph_add_shaders(TARGET <target> GRAPHS <graph.json>...
#                        [TARGETS glsl330 es300 vk450 msl hlsl query-c query-js] [OUTPUT_DIR <dir>]
#                        [TEXTURES] [PRESET <name>])
#
# Compiles graphs with watergraph at build time, before <target> builds. Each graph gives
# <dir>/<name>.<target>.vert/.frag (vk450 also .vert.spv/.frag.spv, es300 also .vert.body/.frag.body)
# and <dir>/<name>.manifest.json;
# query-c gives <dir>/<name>.query.h and query-js <dir>/<name>.query.js, the surface queries
# (docs/queries.md; add <dir> to the target's include directories to include the header);
# a graph is recompiled when its file, a graph it imports (a subgraph), a PNG texture it
# samples, or the watergraph executable changes (watergraph writes a depfile, <dir>/<name>.d,
# which the build reads through add_custom_command's DEPFILE). TARGETS defaults
# to glsl330 es300 vk450, OUTPUT_DIR to ${CMAKE_CURRENT_BINARY_DIR}/watergraph. Relative graph
# paths are relative to ${CMAKE_CURRENT_SOURCE_DIR}.
#
# TEXTURES also writes the node textures a host must upload (built-in ones such as
# water_normal and foam, and the graph's own PNGs), one PNG each beside the shaders, under the
# file name each texture's "file" entry in the manifest gives (<name>.<sampler>.png); they are
# written by the same command as the manifest, so they are current whenever it is. PRESET
# compiles every graph of the call with that preset's values applied (each graph must define
# it; watergraph refuses a graph that does not).
#
# Sets on <target>: the property WATERGRAPH_SHADER_DIR (the output folder), and appends the
# generated files to WATERGRAPH_SHADERS.
include_guard(GLOBAL)
# Depfile paths are absolute; CMP0116 NEW makes Ninja builds read them as such (functions
# keep the policies in effect where they are defined).
if(POLICY CMP0116)
  cmake_policy(SET CMP0116 NEW)
endif()

function(watergraph_add_shaders)
  cmake_parse_arguments(PARSE_ARGV 0 WG "TEXTURES" "TARGET;OUTPUT_DIR;PRESET" "GRAPHS;TARGETS")
  if(WG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "watergraph_add_shaders: unknown arguments: ${WG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT WG_TARGET OR NOT TARGET ${WG_TARGET})
    message(FATAL_ERROR "watergraph_add_shaders: TARGET must name an existing target (got '${WG_TARGET}')")
  endif()
  if(NOT WG_GRAPHS)
    message(FATAL_ERROR "watergraph_add_shaders: GRAPHS needs at least one graph file")
  endif()
  if(NOT WG_TARGETS)
    set(WG_TARGETS glsl330 es300 vk450)
  endif()
  foreach(t IN LISTS WG_TARGETS)
    if(NOT t MATCHES "^(glsl330|es300|vk450|msl|hlsl|query-c|query-js)$")
      message(FATAL_ERROR "watergraph_add_shaders: unknown target '${t}' (glsl330, es300, vk450, msl, hlsl, query-c, query-js)")
    endif()
  endforeach()
  if(NOT WG_OUTPUT_DIR)
    set(WG_OUTPUT_DIR ${CMAKE_CURRENT_BINARY_DIR}/watergraph)
  endif()
  get_filename_component(WG_OUTPUT_DIR "${WG_OUTPUT_DIR}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
  list(JOIN WG_TARGETS "," target_arg)
  set(extra_args)
  if(WG_TEXTURES)
    list(APPEND extra_args --textures)
  endif()
  if(DEFINED WG_PRESET)
    if(WG_PRESET STREQUAL "")
      message(FATAL_ERROR "watergraph_add_shaders: PRESET needs a preset name")
    endif()
    list(APPEND extra_args --preset "${WG_PRESET}")
  elseif("PRESET" IN_LIST WG_KEYWORDS_MISSING_VALUES)
    message(FATAL_ERROR "watergraph_add_shaders: PRESET needs a preset name")
  endif()

  set(WG_PRESET_NOTE)
  if(WG_PRESET)
    set(WG_PRESET_NOTE ", preset ${WG_PRESET}")
  endif()
  set(all_outputs)
  foreach(graph IN LISTS WG_GRAPHS)
    get_filename_component(graph_abs "${graph}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    get_filename_component(name "${graph_abs}" NAME)
    string(REGEX REPLACE "\\.json$" "" name "${name}")
    set(outputs ${WG_OUTPUT_DIR}/${name}.manifest.json)
    foreach(t IN LISTS WG_TARGETS)
      if(t STREQUAL "query-c")
        list(APPEND outputs ${WG_OUTPUT_DIR}/${name}.query.h)
        continue()
      elseif(t STREQUAL "query-js")
        list(APPEND outputs ${WG_OUTPUT_DIR}/${name}.query.js)
        continue()
      endif()
      foreach(stage vert frag)
        list(APPEND outputs ${WG_OUTPUT_DIR}/${name}.${t}.${stage})
        if(t STREQUAL "vk450")
          list(APPEND outputs ${WG_OUTPUT_DIR}/${name}.${t}.${stage}.spv)
        elseif(t STREQUAL "es300")
          # The stage after its version line, for hosts that write that line (three.js).
          list(APPEND outputs ${WG_OUTPUT_DIR}/${name}.${t}.${stage}.body)
        endif()
      endforeach()
    endforeach()
    set(depfile ${WG_OUTPUT_DIR}/${name}.d)
    add_custom_command(
      OUTPUT ${outputs}
      COMMAND watergraph::watergraph compile "${graph_abs}" -o "${WG_OUTPUT_DIR}" --target ${target_arg} --quiet
              ${extra_args} --depfile "${depfile}"
      DEPENDS "${graph_abs}" watergraph::watergraph
      DEPFILE "${depfile}"
      COMMENT "watergraph: compiling ${name}.json (${target_arg}${WG_PRESET_NOTE})"
      VERBATIM)
    list(APPEND all_outputs ${outputs})
  endforeach()

  # A custom target per call, so TARGET may live in another directory than this call.
  set(shader_target ${WG_TARGET}_watergraph_shaders)
  set(n 1)
  while(TARGET ${shader_target})
    math(EXPR n "${n} + 1")
    set(shader_target ${WG_TARGET}_watergraph_shaders_${n})
  endwhile()
  add_custom_target(${shader_target} DEPENDS ${all_outputs})
  add_dependencies(${WG_TARGET} ${shader_target})
  set_property(TARGET ${WG_TARGET} PROPERTY WATERGRAPH_SHADER_DIR "${WG_OUTPUT_DIR}")
  set_property(TARGET ${WG_TARGET} APPEND PROPERTY WATERGRAPH_SHADERS ${all_outputs})
endfunction()
