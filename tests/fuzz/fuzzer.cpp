// libFuzzer entry point; built only in a clang build with -DPLANTFIELD_FUZZ=ON
// (see tools/fuzz.sh).
#include "lsys_fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    pf::fuzz::runLsysInput(data, size);
    return 0;
}
