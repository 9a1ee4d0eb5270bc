#pragma once
// Standard base64 (RFC 4648, '+' '/', '=' padding), used for image data URLs.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace clips::lm {

std::string base64_encode(std::span<const std::uint8_t> bytes);
std::string base64_encode(std::string_view bytes);

// Strict decoder: nullopt on any character outside the alphabet, bad padding
// or a length that is not a multiple of four.
std::optional<std::vector<std::uint8_t>> base64_decode(std::string_view text);

}  // namespace clips::lm
