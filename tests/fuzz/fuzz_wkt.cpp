// libFuzzer: WKT polygons through importPlanFile.
#include "FuzzSupport.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string path = fc::fuzz::scratchPath("input.wkt");
    fc::fuzz::writeBytes(path, data, size);
    fc::fuzz::importExpectingOnlyInputErrors(path);
    return 0;
}
