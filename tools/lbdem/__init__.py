"""lbdem: the Python side of the product (docs/study.md).

One place for launching runs (run), reading their output (io), the reference formulas
(references), the analysis of a settling run (analysis), the initial packing (packing), a
ParaView picture of a run (picture) and the study sweep (study). Plain modules on Debian's
numpy, h5py, matplotlib and PyYAML; run them with /usr/bin/python3 (the interpreter those
packages are installed for; another python3 may come first on PATH).
"""
