#!/usr/bin/env python3
"""How many cells of a run's CSV pandas reads back differently from the text eulerdyn wrote.

eulerdyn writes each f64 in the shortest form that reads back to the same f64 (Python's ``float()`` does). This
counts, for pandas' default parser and for ``float_precision="round_trip"``, the cells whose value differs from
``float()`` of the cell's text, and the largest relative difference:

    python3 tools/pandas_roundtrip.py RUN.csv
"""
import csv
import sys

import pandas as pd


def differences(path, **options):
    """(cells that differ, cells, largest relative difference) of ``pd.read_csv(path, **options)``."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, texts = rows[0], rows[1:]
    frame = pd.read_csv(path, **options)
    differ, largest = 0, 0.0
    for i, row in enumerate(texts):
        for j, text in enumerate(row):
            exact, read = float(text), float(frame.iat[i, j])
            if exact != read:
                differ += 1
                largest = max(largest, abs(read - exact) / abs(exact))
    return differ, len(texts) * len(header), largest


if __name__ == "__main__":
    path = sys.argv[1]
    print(f"pandas {pd.__version__}, {path}")
    for label, options in [("default", {}), ('float_precision="round_trip"', {"float_precision": "round_trip"})]:
        differ, cells, largest = differences(path, **options)
        print(f"{label}: {differ} of {cells} cells differ, largest relative difference {largest:.3g}")
