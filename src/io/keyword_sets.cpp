// *SET_NODE, *SET_PART: a set id, then lines of member ids. *SET_FACE: a set id, then one line
// of corner-node ids per face.
#include "deck_reader.hpp"

namespace abut::deck {
namespace {

// The member ids of a set, any number per line (IMPETUS writes up to 8).
template <typename AddMember>
void read_members(Block& b, AddMember add) {
  if (b.done())
    throw InputError(b.where(), "missing data line: expected the member ids of the set");
  while (!b.done()) {
    std::vector<std::string> names;
    for (std::size_t k = 1; k <= b.peek_fields().size(); ++k)
      names.push_back("id" + std::to_string(k));
    const Row r = b.row(names);
    for (std::size_t k = 0; k < r.size(); ++k) {
      if (r.given(k)) add(r, k);
    }
  }
}

}  // namespace

void read_set_node(DeckReader& d, Block& b) {
  b.title();
  const Row head = b.row({"setid"});
  NodeSet set;
  set.id = d.other_id(head, 0);
  d.claim_id("node set", set.id, head.where(0));
  PendingNodeSet pending;
  pending.index = d.model.node_sets.size();
  read_members(b, [&](const Row& r, std::size_t k) {
    pending.nodes.push_back({d.node_id(r, k), r.where(k)});
  });
  d.model.node_sets.push_back(set);
  d.node_sets.push_back(std::move(pending));
}

void read_set_part(DeckReader& d, Block& b) {
  b.title();
  const Row head = b.row({"setid"});
  PartSet set;
  set.id = d.other_id(head, 0);
  d.claim_id("part set", set.id, head.where(0));
  read_members(b, [&](const Row& r, std::size_t k) {
    set.parts.push_back(d.part_id(r, k));
    d.part_set_members.emplace_back(set.parts.back(), r.where(k));
  });
  d.model.part_sets.push_back(set);
}

// *SET_FACE: one face per row, its 3 or 4 corner nodes (IMPETUS: 4 node ids per face; a
// triangle repeats its third or leaves the fourth empty). Matched to element faces in
// deck_finalize_faces.cpp.
void read_set_face(DeckReader& d, Block& b) {
  b.title();
  const Row head = b.row({"setid"});
  FaceSet set;
  set.id = d.other_id(head, 0);
  set.where = head.where(0);
  d.claim_id("face set", set.id, head.where(0));
  PendingFaceSet pending;
  pending.index = d.model.face_sets.size();
  if (b.done())
    throw InputError(b.where(),
                     "missing data line: expected the corner node ids of a face "
                     "(n1, n2, n3, n4)");
  while (!b.done()) {
    const Row r = b.row({"n1", "n2", "n3", "n4"});
    PendingFaceSet::Face face;
    for (std::size_t k = 0; k < 3; ++k) face.nodes[k] = d.node_id(r, k);
    face.nodes[3] = r.given(3) ? d.node_id(r, 3) : face.nodes[2];
    face.where = r.where();
    pending.faces.push_back(face);
  }
  d.model.face_sets.push_back(set);
  d.face_sets.push_back(std::move(pending));
}

}  // namespace abut::deck
