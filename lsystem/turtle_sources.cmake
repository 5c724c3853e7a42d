# Turtle interpretation into a PlantAsset; included by lsystem/CMakeLists.txt.
# Debian's libtinygltf-dev ships tinygltf compiled (TINYGLTF_IMPLEMENTATION is
# defined inside the library, never here); surfaces_gltf.cpp reads meshes with it.
find_package(TinyGLTF REQUIRED)

target_sources(lsystem PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/turtle.cpp
  ${CMAKE_CURRENT_LIST_DIR}/turtle_builder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surfaces.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surfaces_gltf.cpp
)
target_link_libraries(lsystem PRIVATE TinyGLTF::TinyGLTF)
