#pragma once
// Restart files (issue 13): the complete state of an explicit run at the start of a cycle
// (Simulation::archive) and of its output (schedules, histories, the ParaView series), so that
// `abut run --restart FILE` continues bitwise identically to the run that wrote it.
//
// Layout: the 8 bytes "ABUTRST\n", the format version (uint32), a fingerprint of the model's
// mesh (uint64: nodes, elements, parts), the payload size (uint64), the payload (StateArchive
// bytes) and an FNV-1a checksum of the payload (uint64), all in the machine's byte order. A file
// is written whole to a temporary file and renamed, so an interruption while writing leaves the
// previous restart file intact.
#include <filesystem>

#include "abut/core/state_archive.hpp"
#include "abut/model/model.hpp"

namespace abut::restart_file {

// The name of the restart file in the output directory.
inline constexpr const char* kName = "restart.abr";

void write(const std::filesystem::path& path, const Model& model, const StateArchive& archive);

// The archive for loading. InputError naming the file when it cannot be read, is not a restart
// file, is damaged, comes from another version of abut or from another model.
StateArchive read(const std::filesystem::path& path, const Model& model);

}  // namespace abut::restart_file
