#pragma once
// Start-up checks of a *CONTACT that do not stop the run but deserve a word to the user
// (issue 13): the warnings of its ContactReport.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "abut/model/model.hpp"
#include "abut/solver/contact_report.hpp"

namespace abut {

// A pair of deformable parts whose automatic penalties differ by more than this factor: the
// pair runs with the smaller one (seed 000), an order of magnitude softer than the stiffer side's
// own.
inline constexpr double kGovernedPenaltyRatio = 10.0;

// One warning per such pair of the report (parts and pairs filled in), naming both parts.
std::vector<std::string> penalty_warnings(const Model& model, const ContactReport& report);

// One warning per pair of parts with points that start deeper inside the other than the
// detection depth (ContactInterface::deep_initial_points).
std::vector<std::string> deep_start_warnings(const Model& model, std::int64_t contact_id,
                                             std::span<const DeepStart> deep);

}  // namespace abut
