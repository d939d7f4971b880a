"""What a plot shows as CSV, in long ("tidy") format: one row per sample.

::

    time,topic,field,value
    0.000000,/odom,pose.pose.position.x,0.0
    0.000000,/odom,twist.twist.angular.z,0.5
    0.010000,/odom,pose.pose.position.x,0.02

``time`` is in seconds since the first sample written (microsecond resolution), ``value`` the
exact float. Rows are ordered by time, then by curve in the order given. Long format because
curves from different topics rarely share timestamps: a wide table would be mostly empty
cells, while this one needs no resampling and pivots in one step in a spreadsheet, pandas
(``df.pivot_table(index="time", columns=["topic", "field"])``) or R.
"""
import csv

import numpy as np


def write_tidy_csv(path, curves) -> int:
    """Write ``curves`` [(topic, field path, times, values)] to ``path``; returns the number of rows."""
    times = np.concatenate([np.asarray(curve[2], dtype=float) for curve in curves] or [np.empty(0)])
    values = np.concatenate([np.asarray(curve[3], dtype=float) for curve in curves] or [np.empty(0)])
    owners = np.concatenate([np.full(len(curve[2]), index) for index, curve in enumerate(curves)]
                            or [np.empty(0, int)])
    order = np.lexsort((owners, times))
    start = times.min() if len(times) else 0.0
    with open(path, "w", newline="", encoding="utf-8") as file:
        writer = csv.writer(file)
        writer.writerow(["time", "topic", "field", "value"])
        for row in order:
            topic, field = curves[owners[row]][:2]
            writer.writerow([f"{times[row] - start:.6f}", topic, field, repr(float(values[row]))])
    return len(order)
