"""Decks the Python tests share."""

# A bad field: the program names file, line, keyword and field (docs/deck-reference.md).
BAD_CONTACT = """*UNIT_SYSTEM
SI
*TIME
1e-4
*COMPONENT_BOX
1, 1, 2, 2, 2
0.0, 0.0, 0.0, 0.01, 0.01, 0.01
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
"cube"
1, 1
*CONTACT
1
P, 1, P, 1, 0.3, -1, 0, 1
*END
"""
