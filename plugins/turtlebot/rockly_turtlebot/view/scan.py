"""The laser's scan on the map: a faint ray to each hit and a bright dot on it, closer is warmer."""
import math

from PySide6.QtCore import QLineF, QPointF

from . import model
from .palette import distance_colour
from .shapes import cosmetic_pen, with_alpha

BUCKETS = 12   # rays are drawn in this many colour groups (one pen each)


def scan_hits(snapshot):
    """[(x, y, distance)] in map metres for every beam that hit something."""
    ranges = model.scan(snapshot)
    if not ranges:
        return []
    near, far = model.limits(snapshot)
    x, y, theta = model.pose(snapshot)
    step = 2 * math.pi / len(ranges)
    hits = []
    for index, value in enumerate(ranges):
        distance = model.hit(value, near, far)
        if distance is not None:
            angle = theta + index * step
            hits.append((x + distance * math.cos(angle), y + distance * math.sin(angle), distance))
    return hits


def paint_scan(p, snapshot, u):
    """Rays and dots, painted in map metres (the painter's transform is the map's)."""
    hits = scan_hits(snapshot)
    if not hits:
        return
    x, y, _ = model.pose(snapshot)
    groups = [[] for _ in range(BUCKETS)]
    for hx, hy, distance in hits:
        groups[min(BUCKETS - 1, int(distance / 2.0 * BUCKETS))].append((hx, hy))
    origin = QPointF(x, y)
    for bucket, points in enumerate(groups):
        if not points:
            continue
        colour = distance_colour((bucket + 0.5) * 2.0 / BUCKETS)
        p.setPen(cosmetic_pen(with_alpha(colour, 0.3 - 0.15 * bucket / BUCKETS), max(1.0, 1.1 * u)))
        p.drawLines([QLineF(origin, QPointF(hx, hy)) for hx, hy in points])
        p.setPen(cosmetic_pen(colour, max(2.5, 4.0 * u), round_caps=True))
        p.drawPoints([QPointF(hx, hy) for hx, hy in points])
