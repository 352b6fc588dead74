#include "contact_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>
#include <utility>

namespace abut {

// The automatic penalty of a part grows with its bulk modulus and falls with the size of its
// smallest element (seed 000); a pair takes the smaller of its two parts' penalties. When one side
// has much larger (or softer) elements, the other side's points penetrate it as deep as that
// side's soft springs allow, an order of magnitude deeper than their own penalty would let them:
// the user may want pfac, a pair scale factor or a finer mesh there.
std::vector<std::string> penalty_warnings(const Model& model, const ContactReport& report) {
  std::map<std::int64_t, const PartPenalty*> by_part;
  for (const PartPenalty& p : report.parts) by_part[p.part_id] = &p;
  std::set<std::pair<std::int64_t, std::int64_t>> seen;
  std::vector<std::string> out;
  for (const PairStiffness& pair : report.pairs) {
    const auto key = std::minmax(pair.part1, pair.part2);
    if (pair.part1 == pair.part2 || !seen.insert(key).second) continue;
    const auto a = by_part.find(key.first), b = by_part.find(key.second);
    if (a == by_part.end() || b == by_part.end()) continue;
    const PartPenalty& pa = *a->second;
    const PartPenalty& pb = *b->second;
    if (!pa.automatic || !pb.automatic || !(pa.penalty > 0.0) || !(pb.penalty > 0.0)) continue;
    if (is_rigid(model.material_of_part(pa.part_id)) ||
        is_rigid(model.material_of_part(pb.part_id)))
      continue;  // a rigid part's penalty follows the impact speed, not its elements
    const PartPenalty& soft = pa.penalty < pb.penalty ? pa : pb;
    const PartPenalty& stiff = pa.penalty < pb.penalty ? pb : pa;
    const double ratio = stiff.penalty / soft.penalty;
    if (ratio < kGovernedPenaltyRatio) continue;
    out.push_back(fmt::format(
        "contact {}: parts {} and {} touch with part {}'s automatic penalty {:.3g}, {:.3g} times "
        "below part {}'s ({:.3g}; the pair takes the smaller, seed 000): part {}'s larger or "
        "softer elements let part {} penetrate deeper than its own penalty would. Give {}, {} "
        "or refine part {} near the contact if that matters",
        report.id, key.first, key.second, soft.part_id, soft.penalty, ratio, stiff.part_id,
        stiff.penalty, soft.part_id, stiff.part_id, model.sources.words("penalty"),
        model.sources.words("pair_penalty_scale"), soft.part_id));
  }
  return out;
}

std::vector<std::string> deep_start_warnings(const Model& model, std::int64_t contact_id,
                                             std::span<const DeepStart> deep) {
  std::vector<std::string> out;
  for (const DeepStart& d : deep)
    out.push_back(fmt::format(
        "contact {}: {} contact point{} of part {} start{} inside part {}, up to {:.3g} deep, "
        "below the detection depth {:.3g}: the contact search does not reach {}, so nothing "
        "pushes {} out. Move the parts apart, or give a larger detection depth ({})",
        contact_id, d.points, d.points == 1 ? "" : "s", d.part, d.points == 1 ? "s" : "",
        d.other_part, d.deepest, d.detection_depth, d.points == 1 ? "it" : "them",
        d.points == 1 ? "it" : "them", model.sources.words("detection_depth")));
  return out;
}

}  // namespace abut
