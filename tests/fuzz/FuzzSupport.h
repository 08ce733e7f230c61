// libFuzzer harness support: the importers read files, so each input is written to a
// per-process scratch file first. Only InputError may escape an importer; anything else
// (another exception, a crash, a hang) is a finding.
#pragma once

#include "importers/Import.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace fc::fuzz {

// A file in this process's own scratch folder (/tmp/fc-fuzz-PID/NAME).
inline std::string scratchPath(const std::string& name) {
    const std::string folder = "/tmp/fc-fuzz-" + std::to_string(::getpid());
    std::filesystem::create_directories(folder);
    return folder + "/" + name;
}

inline void writeBytes(const std::string& path, const uint8_t* data, size_t size) {
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

inline void importExpectingOnlyInputErrors(const std::string& path) {
    try {
        previewImport(path);
        importPlanFile(path);
    } catch (const InputError&) {
    }
}

} // namespace fc::fuzz
