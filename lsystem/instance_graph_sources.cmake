# The InstanceGraph: b-grammar nodes with turtle status functions, transforms and bounds; included by lsystem/CMakeLists.txt.
target_sources(lsystem PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/instance_graph.cpp
  ${CMAKE_CURRENT_LIST_DIR}/instance_graph_build.cpp
  ${CMAKE_CURRENT_LIST_DIR}/instance_key.cpp
  ${CMAKE_CURRENT_LIST_DIR}/status_function.cpp
)
