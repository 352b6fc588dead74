#include "abut/contact/surface.hpp"

namespace abut {

ContactSurface make_contact_surface(std::span<const SkinFace> faces,
                                    const std::function<double(std::int64_t part)>& penalty_of_part) {
  ContactSurface s;
  s.facets.reserve(faces.size());
  for (const SkinFace& f : faces) s.add(f.nodes, f.part, penalty_of_part(f.part), f.thickness);
  return s;
}

}  // namespace abut
