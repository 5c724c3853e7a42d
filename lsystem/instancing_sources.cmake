# The b-grammar / InstanceGraph (seed 000); included by lsystem/CMakeLists.txt.
target_sources(lsystem PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/bgrammar.cpp
  ${CMAKE_CURRENT_LIST_DIR}/bgrammar_draft.cpp
  ${CMAKE_CURRENT_LIST_DIR}/bgrammar_memoised.cpp
  ${CMAKE_CURRENT_LIST_DIR}/sequitur.cpp
)
