"""Straight wires cut into segments, welded where they meet: the shared part of the scripts that
write wire meshes (make-wire-chair.py, make-frame-tower.py). Standard library only."""
import math


class WireMesh:
    def __init__(self, segment):
        self.segment = segment  # m, longest segment of a member
        self.vertices = []      # (x, y, z), rounded so that shared joints weld
        self.edges = []         # (i, j) vertex ids
        self._index = {}

    def vertex(self, p):
        key = tuple(round(c, 9) for c in p)
        if key not in self._index:
            self._index[key] = len(self.vertices)
            self.vertices.append(key)
        return self._index[key]

    def member(self, p, q, segments=None):
        """A straight wire from p to q in `segments` equal parts, by default as few as keep each
        no longer than `segment`."""
        n = segments or max(1, math.ceil(math.dist(p, q) / self.segment - 1e-9))
        ids = [self.vertex(tuple(a + (b - a) * k / n for a, b in zip(p, q))) for k in range(n + 1)]
        self.edges.extend(zip(ids[:-1], ids[1:]))

    def check(self):
        """No edge twice, and every vertex reachable from the first: one piece of wire."""
        assert len({frozenset(e) for e in self.edges}) == len(self.edges), "an edge twice"
        reached = {0}
        while True:
            grown = reached | {b for a, b in self.edges if a in reached} | \
                    {a for a, b in self.edges if b in reached}
            if grown == reached:
                break
            reached = grown
        assert len(reached) == len(self.vertices), "the wires fall apart"
