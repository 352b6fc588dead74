#!/usr/bin/env python3
"""Seed corpus for the libFuzzer targets (fuzz/README.md): the deck files of examples/ and
tests/**/decks/, and the decks written as raw strings R"(...)" in tests/io/*.cpp.

    fuzz/make_corpus.py keyword /tmp/corpus-keyword     # .k decks
    fuzz/make_corpus.py inp /tmp/corpus-inp             # .inp decks
    fuzz/make_corpus.py msh /tmp/corpus-msh             # Gmsh .msh meshes (ASCII and binary)
"""
import hashlib
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parent.parent
fmt, out = sys.argv[1], pathlib.Path(sys.argv[2])
out.mkdir(parents=True, exist_ok=True)
suffix = {"keyword": ".k", "inp": ".inp", "msh": ".msh"}[fmt]
decks = [p.read_bytes() for p in sorted(root.glob("examples/**/*" + suffix))]
decks += [p.read_bytes() for p in sorted(root.glob("tests/**/decks/*" + suffix))]
for source in sorted(root.glob("tests/io/*.cpp")) if fmt != "msh" else []:
    is_inp = "inp" in source.name
    if is_inp != (fmt == "inp"):
        continue
    for text in re.findall(r'R"\((.*?)\)"', source.read_text(), re.S):
        if "*" in text:
            decks.append(text.encode())
for deck in decks:
    (out / hashlib.sha1(deck).hexdigest()).write_bytes(deck)
print(len(list(out.iterdir())), "seeds in", out)
