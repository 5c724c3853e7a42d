# The b-grammar / InstanceGraph (seed 000); included by lsystem/CMakeLists.txt.
