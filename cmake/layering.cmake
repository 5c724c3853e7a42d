# Folders of static libraries, one per concern, whose direction of use is
# part of the build (engine/CMakeLists.txt, lsystem/CMakeLists.txt): a library
# links only the libraries it USES, and check_layering.cmake runs before it
# compiles, failing, naming file:line, on any `#include "PREFIX/<folder>/…"`
# of a folder it does not use (directly or through what it uses). CPU_ONLY
# libraries compile with a Vulkan and GLFW header guard first on their
# include path (PLANTFIELD_CPU_ONLY_GUARD), so including either, directly or
# through another header, is a compile error.

set(PLANTFIELD_CPU_ONLY_GUARD ${PROJECT_BINARY_DIR}/cpu_only_guard)
foreach(header vulkan/vulkan.h vulkan/vulkan_core.h GLFW/glfw3.h)
  file(WRITE ${PLANTFIELD_CPU_ONLY_GUARD}/${header}
       "#error \"a CPU-only library includes <${header}>: move the code that needs it to engine/vk or above\"\n")
endforeach()

# plantfield_layered_library(TARGET PREFIX prefix FOLDER folder [CPU_ONLY] SOURCES … [HEADERS …] [USES targets …])
# builds the static library TARGET from PREFIX/FOLDER/SOURCES. The sources
# and the headers named like them are checked, and HEADERS besides (a
# folder's headers without a source of their own; a folder may hold two
# libraries, so they are named).
function(plantfield_layered_library target)
  cmake_parse_arguments(ARG "CPU_ONLY" "PREFIX;FOLDER" "SOURCES;HEADERS;USES" ${ARGN})
  set(folder_dir ${PROJECT_SOURCE_DIR}/${ARG_PREFIX}/${ARG_FOLDER})
  list(TRANSFORM ARG_SOURCES PREPEND ${folder_dir}/)
  list(TRANSFORM ARG_HEADERS PREPEND ${folder_dir}/)
  add_library(${target} STATIC ${ARG_SOURCES})
  if(ARG_CPU_ONLY)
    target_include_directories(${target} BEFORE PRIVATE ${PLANTFIELD_CPU_ONLY_GUARD})
  endif()
  set(folders ${ARG_FOLDER})
  foreach(dep ${ARG_USES})
    target_link_libraries(${target} PUBLIC ${dep})
    get_property(dep_folders GLOBAL PROPERTY PLANTFIELD_LAYER_FOLDERS_${dep})
    list(APPEND folders ${dep_folders})
  endforeach()
  list(REMOVE_DUPLICATES folders)
  set_property(GLOBAL PROPERTY PLANTFIELD_LAYER_FOLDERS_${target} ${folders})

  set(headers ${ARG_HEADERS})
  foreach(source ${ARG_SOURCES})
    string(REGEX REPLACE "\\.cpp$" ".h" header ${source})
    if(EXISTS ${header})
      list(APPEND headers ${header})
    endif()
  endforeach()
  list(REMOVE_DUPLICATES headers)
  set(stamp ${CMAKE_CURRENT_BINARY_DIR}/${target}.layering)
  set(script ${PROJECT_SOURCE_DIR}/cmake/check_layering.cmake)
  add_custom_command(
    OUTPUT ${stamp}
    COMMAND ${CMAKE_COMMAND} -DLIBRARY=${target} -DPREFIX=${ARG_PREFIX} "-DALLOWED=${folders}"
            "-DSOURCES=${ARG_SOURCES};${headers}" -DSTAMP=${stamp} -P ${script}
    DEPENDS ${ARG_SOURCES} ${headers} ${script}
    COMMENT "layering of ${target}"
    VERBATIM)
  add_custom_target(${target}_layering DEPENDS ${stamp})
  add_dependencies(${target} ${target}_layering)
endfunction()
