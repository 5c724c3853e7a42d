# The InstanceGraph: b-grammar nodes with turtle status functions, transforms and bounds; included by lsystem/CMakeLists.txt.
