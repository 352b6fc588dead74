#!/bin/sh
# Writes a libFuzzer dictionary (-dict=) of the keywords the readers accept, taken from their
# catalogues (the `supported()` tables), plus entity words and hostile numbers; fuzz/README.md.
#   fuzz/make_dict.sh keyword > /tmp/keyword.dict
#   fuzz/make_dict.sh inp > /tmp/inp.dict
set -eu
root=$(dirname "$0")/..
case "${1:-keyword}" in
  keyword) catalogue="$root/src/io/deck_catalogue.cpp" ;;
  inp) catalogue="$root/src/io/inp/inp_catalogue.cpp" ;;
  *) echo "usage: $0 keyword|inp" >&2; exit 2 ;;
esac
awk '/supported\(\) \{/,/^  \};/' "$catalogue" | grep -oE '\{"\*[A-Z0-9 _-]+"' | tr -d '{' |
  sort -u | sed 's/^/kw=/'
for word in '*END' '*INCLUDE' 'P' 'PS' 'NS' 'ALL' 'N' 'G' 'fcn(' '&' 'nan' 'inf' '-1' '0' \
  '1e308' '9223372036854775807' '2147483648' ',' ',,' '\x0A' '\x0D\x0A'; do
  printf 'w="%s"\n' "$word"
done | awk '{ sub(/^w=/, "x" NR "="); print }'
