// The fixed colour set of all renderings. The GIF palette is built from it,
// so flat areas quantise exactly.
#pragma once

#include <string_view>
#include <vector>

#include "render/image.hpp"

namespace clips::render {

namespace theme {
inline constexpr Rgb background{255, 255, 255};
inline constexpr Rgb floor{246, 243, 235};
inline constexpr Rgb gridline{222, 216, 202};
inline constexpr Rgb wall{56, 58, 72};
inline constexpr Rgb wall_edge{82, 85, 102};
inline constexpr Rgb text{33, 33, 40};
inline constexpr Rgb muted{112, 112, 124};
inline constexpr Rgb human{128, 62, 168};
inline constexpr Rgb robot{72, 88, 104};
inline constexpr Rgb robot_eye{120, 230, 255};
inline constexpr Rgb marker{255, 140, 0};
inline constexpr Rgb track{230, 230, 236};
inline constexpr Rgb panel{250, 248, 242};
inline constexpr Rgb panel_edge{205, 200, 188};
inline constexpr Rgb neutral{150, 150, 160};
}  // namespace theme

// Fills that quantise exactly in GIFs (with the named colours and the theme):
// the pastels that items of unlisted types get, and a few card-header tints.
// A pack's scene colours may be any colour; these stay exact in animations.
const std::vector<Rgb>& pastel_colours();
const std::vector<Rgb>& card_header_colours();

// "red", "yellow", "blue", "green", "pink" (case-insensitive); anything else,
// including "", gives theme::neutral.
Rgb named_colour(std::string_view name);

// Darker / lighter shades used for outlines and highlights.
Rgb shade(Rgb c, double factor);   // factor < 1 darkens
Rgb tint(Rgb c, double amount);    // mixes towards white, amount in [0,1]

// Every colour the renderers paint as a flat area (theme, named colours and
// their shades, pastel item colours), without duplicates.
std::vector<Rgb> theme_colours();

// The pastel an item type without a colour of its own gets on a card scene
// (a hash of the type: stable across runs).
Rgb hashed_pastel(std::string_view item_type);

}  // namespace clips::render
