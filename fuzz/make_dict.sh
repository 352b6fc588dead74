#!/bin/sh
# Writes a libFuzzer dictionary (-dict=) of the keywords the readers accept, taken from their
# catalogues (the `supported()` tables), plus entity words and hostile numbers; fuzz/README.md.
#   fuzz/make_dict.sh keyword > /tmp/keyword.dict
#   fuzz/make_dict.sh inp > /tmp/inp.dict
#   fuzz/make_dict.sh msh > /tmp/msh.dict
set -eu
root=$(dirname "$0")/..
case "${1:-keyword}" in
  keyword) catalogue="$root/src/io/deck_catalogue.cpp" ;;
  inp) catalogue="$root/src/io/inp/inp_catalogue.cpp" ;;
  msh)
    # The section names of the .msh format 4.1 and the element types the reader knows.
    for word in '$MeshFormat' '$EndMeshFormat' '$PhysicalNames' '$EndPhysicalNames' '$Entities' \
      '$EndEntities' '$Nodes' '$EndNodes' '$Elements' '$EndElements' '$Comments' '$EndComments' \
      '$PartitionedEntities' '4.1 0 8' '4.1 1 8' '2.2 0 8' '\x0A' '"'; do
      printf 'w="%s"\n' "$word"
    done | awk '{ sub(/^w=/, "s" NR "="); print }'
    for word in 15 1 8 2 3 9 16 10 4 11 5 17 12 6 7 -1 0 nan 1e308 18446744073709551615; do
      printf 'n%s="%s"\n' "$(echo "$word" | tr -c '0-9a-z' '_')" "$word"
    done
    exit 0 ;;
  *) echo "usage: $0 keyword|inp|msh" >&2; exit 2 ;;
esac
awk '/supported\(\) \{/,/^  \};/' "$catalogue" | grep -oE '\{"\*[A-Z0-9 _-]+"' | tr -d '{' |
  sort -u | sed 's/^/kw=/'
for word in '*END' '*INCLUDE' 'P' 'PS' 'NS' 'ALL' 'N' 'G' 'fcn(' '&' 'nan' 'inf' '-1' '0' \
  '1e308' '9223372036854775807' '2147483648' ',' ',,' '\x0A' '\x0D\x0A'; do
  printf 'w="%s"\n' "$word"
done | awk '{ sub(/^w=/, "x" NR "="); print }'
