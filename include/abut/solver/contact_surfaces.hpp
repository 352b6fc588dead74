#pragma once
// From the model's hexes to the contact library's plain arrays: the contact surface of a list of
// skin faces (penalty, bulk modulus and element volume of each facet's owner) and the smallest
// element of a part (the L_min of seed 000's automatic penalty).
#include <cstdint>
#include <functional>
#include <span>

#include "abut/contact/surface.hpp"
#include "abut/mesh/mesh.hpp"
#include "abut/mesh/skin.hpp"

namespace abut {

// `penalty_of_part`: pfac of each part; `bulk_of_part`: bulk modulus of each part (Radioss
// stiffness rules; may be empty).
ContactSurface contact_surface(const Mesh& mesh, std::span<const SkinFace> faces,
                               const std::function<double(std::int64_t part)>& penalty_of_part,
                               const std::function<double(std::int64_t part)>& bulk_of_part = {});

// Volume of the smallest element of a part (the hexes *CHANGE_P-ORDER made of one element count
// together); InputError if the part has no hex.
double smallest_element_volume(const Mesh& mesh, std::int64_t part);

}  // namespace abut
