#pragma once
// Bytes as base64 text and back (RFC 4648, with '=' padding): how the WebGPU executor hands
// texels, uniform buffers and frames to its helper in JSON lines without a number per float.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace wg::accuracy {

std::string base64Text(const void* bytes, size_t size);
// nullopt for text that is not base64.
std::optional<std::vector<std::uint8_t>> bytesOfBase64Text(const std::string& text);

}  // namespace wg::accuracy
