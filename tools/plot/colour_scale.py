"""The colour scale of a field map, one rule for every figure of mpmx (points2d.py,
jet_maps.py, jet_compare.py): a field that takes both signs (a stress) in a diverging,
perceptually uniform map (RdBu_r) centred on zero with symmetric limits, so that white is
zero and equal tension and compression are equally dark (a stress or velocity component
always: its zero means something); a field of one sign (density, temperature) in viridis. The limits are the 1st and 99th percentiles of the values (a few
points at a contact would leave the rest one colour), and caption() says how many values
lie beyond them and their extremes.
"""

import numpy as np

DIVERGING, SEQUENTIAL = "RdBu_r", "viridis"
CLIP_PERCENT = 1.0
EMPTY = "0.82"  # the axes' colour where there is no material (white is zero stress)


class Scale:
    """`centred`: a quantity whose zero means something (a stress, a velocity) keeps the
    diverging map about zero even when the values shown take one sign (a gas's
    compression: the blue half alone)."""

    def __init__(self, values, vmin=None, vmax=None, cmap=None, centred=False):
        v = np.asarray(values, dtype=float).ravel()
        self.values = v[np.isfinite(v)]
        if self.values.size == 0:
            raise ValueError("no finite value to scale")
        lo = vmin if vmin is not None else float(np.percentile(self.values, CLIP_PERCENT))
        hi = vmax if vmax is not None else float(np.percentile(self.values, 100 - CLIP_PERCENT))
        self.signed = centred or float(self.values.min()) < 0.0 < float(self.values.max())
        self.cmap = cmap or (DIVERGING if self.signed else SEQUENTIAL)
        self.symmetric = self.signed and vmin is None and vmax is None and not cmap
        self.chosen = vmin is not None or vmax is not None
        if self.symmetric:
            m = max(abs(lo), abs(hi))
            lo, hi = -m, m
        if not hi > lo:  # a uniform field (t = 0) still needs a scale
            lo, hi = float(self.values.min()), float(self.values.max())
        if not hi > lo:
            pad = max(abs(lo) * 0.05, 1e-12)
            lo, hi = lo - pad, hi + pad
        self.lo, self.hi = lo, hi
        self.below = int(np.sum(self.values < lo))
        self.above = int(np.sum(self.values > hi))

    @property
    def extend(self):
        """The colour bar's arrows: which ends have values beyond them."""
        return {(False, False): "neither", (True, False): "min", (False, True): "max",
                (True, True): "both"}[(self.below > 0, self.above > 0)]

    def caption(self, unit=""):
        """'colour limits [-66.4, 66.4] GPa (1st-99th percentile, symmetric about 0; of
        13440 values: 128 below (down to -69.6 GPa))'."""
        u = f" {unit}" if unit else ""
        clipped = []
        if self.below:
            clipped.append(f"{self.below} below (down to {float(self.values.min()):.3g}{u})")
        if self.above:
            clipped.append(f"{self.above} above (up to {float(self.values.max()):.3g}{u})")
        how = ("limits set" if self.chosen else
               f"{CLIP_PERCENT:g}st-{100 - CLIP_PERCENT:g}th percentile" + (", symmetric about 0" if self.symmetric else ""))
        return (f"colour limits [{self.lo:.3g}, {self.hi:.3g}]{u} ({how}; of {self.values.size} values: "
                + (", ".join(clipped) if clipped else "none beyond") + ")")
