// libFuzzer entry point, built once per target (PLANTFIELD_FUZZ_TARGET names
// the function of fuzz_targets.h) in a clang build with -DPLANTFIELD_FUZZ=ON;
// see tools/fuzz.sh.
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    pf::fuzz::PLANTFIELD_FUZZ_TARGET(data, size);
    return 0;
}
