# Turtle interpretation into a PlantAsset; included by lsystem/CMakeLists.txt.
target_sources(lsystem PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/turtle.cpp
)
