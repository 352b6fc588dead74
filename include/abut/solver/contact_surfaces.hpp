#pragma once
// From the model's hexes and shells to the contact library's plain arrays: the contact surface of
// a list of faces (exterior faces of hexes; shells, two-sided), with the penalty, moduli and
// element volume of each facet's owner, and the smallest element of a part (the L_min of seed
// 000's automatic penalty).
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "abut/contact/laws/normal.hpp"
#include "abut/contact/surface.hpp"
#include "abut/mesh/mesh.hpp"
#include "abut/mesh/skin.hpp"
#include "abut/model/model.hpp"

namespace abut {

// `penalty_of_face`: pfac of each facet; `moduli_of_part`: bulk and shear modulus of each part
// (Radioss stiffness rules: B for solids, E for shells; may be empty).
// `shell_sides`: both sides of each shell, or one (OptiStruct MORIENT NORM / REVNORM; OVERLAP:
// the side `overlap_reversed` gives each face, shell_orientation.hpp). `parents`: empty, or the
// curved face of each of `faces` (curved_faces.hpp).
ContactSurface contact_surface(
    const Mesh& mesh, std::span<const SkinFace> faces,
    const std::function<double(const SkinFace&)>& penalty_of_face,
    const std::function<ElasticModuli(std::int64_t part)>& moduli_of_part = {},
    ContactSpec::ShellSides shell_sides = ContactSpec::ShellSides::Both,
    std::span<const FacetParent> parents = {}, std::span<const std::uint8_t> overlap_reversed = {});

// OptiStruct MORIENT OVERLAP: for each of `main_faces`, whether its shell pushes against its
// normal, from where the secondary surface's nodes (`secondary_faces`' and `secondary_nodes`) lie
// through the shells at the start (shell_orientation.hpp). Entries of solid faces are 0.
std::vector<std::uint8_t> overlap_sides(const Mesh& mesh, std::span<const SkinFace> secondary_faces,
                                        std::span<const std::int32_t> secondary_nodes,
                                        std::span<const SkinFace> main_faces);

// Element-based automatic penalty (*CONTACT_STIFFNESS ELEMENT, in the spirit of Abaqus/Explicit's
// default general-contact penalty, seed 001): the facet's spring on its lightest node adds at most
// a fraction eps of the owning element's own largest eigenfrequency squared,
//     2 pfac A / m_min = eps omega_e^2,   omega_e = 2 / dt_e,
// so that the highest frequency of the node with both springs, at most sqrt(1 + eps) omega_e,
// lowers the stable step by no more than the seed's 4% for a scale factor of 1:
// eps = 1/0.96^2 - 1. `element_step`: dt_e of the face's hex; `lightest_node`: m_min.
inline constexpr double kElementPenaltyFraction = 1.0 / (0.96 * 0.96) - 1.0;
double element_penalty(double element_step, double lightest_node, double face_area);

// The contact faces of a contact entity (P, PS or ALL): the exterior faces of its hexes, then its
// shells; InputError if it has none. With `exposed_faces` (IMPETUS no_internal = 0) also the
// interior faces that the erosion of a neighbouring hex would expose.
std::vector<SkinFace> contact_faces(const Model& model, const EntityRef& entity, bool merge,
                                    bool exposed_faces = false);

// The element index the contact library's erosion uses (ContactSurface::element): a hex's own
// index, shells after all hexes.
std::int32_t element_index(const Mesh& mesh, const SkinFace& f);

// Can elements of the part erode (*PART erosion criteria or a failure law of its material)?
bool part_can_erode(const Model& model, std::int64_t part);

// OptiStruct ADJUST of every contact that asks for it (ContactSpec::adjust_depth): moves surface-1
// nodes within the depth onto surface 2 in the reference configuration. Returns one note each.
std::vector<std::string> adjust_contact_nodes(Model& model);

// Volume of the smallest element of a part (the hexes *CHANGE_P-ORDER made of one element count
// together; a shell's volume is its area times `shell_thickness`); InputError if the part has no
// element.
double smallest_element_volume(const Mesh& mesh, std::int64_t part, double shell_thickness = 0.0);

// The normal law of a pressure-penetration curve (*CONTACT_NORMAL CURVE, .inp TABULAR): a *CURVE
// is read at the penetration d; a *FUNCTION gets d as its t (as fcn(fid, d) would) and the end
// time as term.
CurvePenalty curve_penalty(const Model& model, FunctionRef curve);

// A *CURVE or *FUNCTION as a function of one variable x (a *FUNCTION gets x as its t and `term`
// as term); empty when the reference is not valid. `table` must outlive the result.
ScalarFunction function_of_one(const FunctionTable* table, FunctionRef f, double term);

}  // namespace abut
