# Installs the gltf-validator pinned by package-lock.json into DIR with
# `npm ci`, unless exactly that version is already there: only the first run
# in a build tree needs the npm registry.
# Usage: cmake -DNPM=path/to/npm -DDIR=validator/dir -P install_validator.cmake
file(READ ${DIR}/package-lock.json lock)
string(JSON wanted GET "${lock}" packages node_modules/gltf-validator version)
set(installed ${DIR}/node_modules/gltf-validator/package.json)
if(EXISTS ${installed})
  file(READ ${installed} manifest)
  string(JSON have GET "${manifest}" version)
  if(have STREQUAL wanted)
    message(STATUS "gltf-validator ${have} already installed in ${DIR}")
    return()
  endif()
endif()
execute_process(COMMAND ${NPM} ci --prefix ${DIR} --no-audit --no-fund --loglevel=error RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "npm ci of gltf-validator ${wanted} failed (${result}); the first run needs the npm registry")
endif()
