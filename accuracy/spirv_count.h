#pragma once
// The size of a SPIR-V module after spirv-opt's performance recipe (-O), in instructions:
// a driver-independent cost figure for the bench beside the measured time.
#include <cstdint>
#include <string>
#include <vector>

namespace wg::accuracy {

// Words from the bytes of a .spv file (little-endian, as watergraph writes them).
std::vector<uint32_t> spirvWords(const std::string& bytes);
// Instructions after optimisation; -1 when the optimiser rejects the module.
int optimisedInstructionCount(const std::vector<uint32_t>& words);

}  // namespace wg::accuracy
