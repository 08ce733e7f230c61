// libFuzzer: DXF drawings through importPlanFile (GDAL's OGR, chaining, assembly, validation).
#include "FuzzSupport.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string path = fc::fuzz::scratchPath("input.dxf");
    fc::fuzz::writeBytes(path, data, size);
    fc::fuzz::importExpectingOnlyInputErrors(path);
    return 0;
}
