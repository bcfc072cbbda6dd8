"""Unit labels for mpmx figures, from the run's named unit system.

A run whose deck names a unit system in `case.units` (nm_ps_GPa, mm_us_GPa, metal, SI)
records it in run.json as units.name; any other `case.units` is free text, which the
figures show as it is (a dimensionless case has no units to put on an axis).
"""

import json
import os

# Units of each quantity in each named system (src/mpmx/core/units.hpp): mass is
# stress x length x time^2, so nm_ps_GPa's is 1e-24 kg and mm_us_GPa's 1e-6 kg.
SYSTEMS = {
    "nm_ps_GPa": dict(length="nm", time="ps", stress="GPa", velocity="km/s", density="g/cm$^3$",
                      mass="10$^{-24}$ kg", volume="nm$^3$", rate="1/ps", energy="10$^{-18}$ J"),
    "mm_us_GPa": dict(length="mm", time="$\\mu$s", stress="GPa", velocity="km/s", density="g/cm$^3$",
                      mass="mg", volume="mm$^3$", rate="1/$\\mu$s", energy="J"),
    "metal": dict(length="$\\AA$", time="ps", stress="amu/($\\AA$ ps$^2$)", velocity="$\\AA$/ps",
                  density="amu/$\\AA^3$", mass="amu", volume="$\\AA^3$", rate="1/ps",
                  energy="amu $\\AA^2$/ps$^2$"),
    "SI": dict(length="m", time="s", stress="Pa", velocity="m/s", density="kg/m$^3$", mass="kg",
               volume="m$^3$", rate="1/s", energy="J"),
}

# The quantity of each field an mpmx run writes (particles.csv, nodes.csv, the .vtu/.vti).
QUANTITY = {
    "x": "length", "y": "length", "z": "length", "position": "length", "displacement": "length",
    "front": "length", "dx": "length", "time": "time", "t": "time",
    "stress": "stress", "pressure": "stress", "velocity": "velocity", "density": "density",
    "mass": "mass", "volume": "volume", "velocity_gradient": "rate", "energy": "energy",
    "strain": None,
}


def find_run_json(source):
    """run.json of a run directory, or of the run a .pvd/.vtu/.vti belongs to (its folder
    or the one above, for vtk/NAME.vtu); None when there is none."""
    d = source if os.path.isdir(source) else os.path.dirname(os.path.abspath(source))
    for folder in (d, os.path.dirname(d)):
        path = os.path.join(folder, "run.json")
        if os.path.isfile(path):
            return path
    return None


class Units:
    """The units of one run: unit(quantity) gives "nm", "GPa", ... or "" when unknown."""

    def __init__(self, name=None, text="", length=""):
        self.name = name if name in SYSTEMS else None
        self.text = text
        self.length = length  # a run in no named system that states its images' length unit

    @classmethod
    def of_record(cls, record):
        name = (record.get("units") or {}).get("name") if isinstance(record, dict) else None
        case = ((record.get("deck") or {}).get("case") or {}) if isinstance(record, dict) else {}
        text = str(case.get("units", "") or "")
        # A direct-MD jet run (metal units inside) writes its ParaView bins in nm.
        length = str(((record.get("jet") or {}) if isinstance(record, dict) else {}).get("bins_series_length_unit", ""))
        return cls(name or (text if text in SYSTEMS else None), text, length)

    @classmethod
    def of_source(cls, source):
        path = find_run_json(source)
        if path is None:
            return cls()
        try:
            with open(path) as f:
                return cls.of_record(json.load(f))
        except (OSError, ValueError):
            return cls()

    def unit(self, quantity):
        if not self.name:
            return self.length if quantity == "length" else ""
        return SYSTEMS[self.name].get(quantity, "") if quantity else ""

    def of_field(self, field):
        return self.unit(QUANTITY.get(field))

    def label(self, text, quantity):
        """'text (unit)', or text alone when the unit is not known."""
        u = self.unit(quantity)
        return f"{text} ({u})" if u else text

    def note(self):
        """What a figure without named units should say about them: the deck's own text
        (e.g. 'dimensionless (E = rho0 = 1, c = 1)'), or ''."""
        return "" if self.name or not self.text else f"units: {self.text}"


def shown(text):
    """Text from a deck (case id, title) for a figure: control characters written \\xNN,
    as mpmx prints them (matplotlib's missing-glyph warnings would echo them raw)."""
    return "".join(c if ord(c) >= 0x20 and ord(c) != 0x7F else f"\\x{ord(c):02x}" for c in str(text))
