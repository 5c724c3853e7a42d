# Meshes of a PlantAsset and its export to glTF 2.0 and OBJ, and the
# InstanceGraph's export to glTF; included by
# lsystem/CMakeLists.txt after add_library(lsystem …).
# Debian ships tinygltf compiled as libtinygltf.so (with its stb and
# nlohmann-json implementation inside), so nothing here defines
# TINYGLTF_IMPLEMENTATION; nothing else in the project may either.
find_package(TinyGLTF REQUIRED)

target_sources(lsystem PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/primitive_mesh.cpp
  ${CMAKE_CURRENT_LIST_DIR}/plant_export.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gltf_builder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gltf_export.cpp
  ${CMAKE_CURRENT_LIST_DIR}/graph_export.cpp
  ${CMAKE_CURRENT_LIST_DIR}/obj_export.cpp
)
target_link_libraries(lsystem PRIVATE TinyGLTF::TinyGLTF)
