"""Regenerate sinktheory/_generated/ from the symbolic model.

    python derivations/generate_kernels.py

Prints the files written.  Commit the result; tests/foundations/test_generated.py fails whenever the
checked-in kernels differ from what this script produces.
"""

from sinktheory import codegen

if __name__ == "__main__":
    for path in codegen.write():
        print(path)
