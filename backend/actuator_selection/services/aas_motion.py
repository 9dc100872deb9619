"""The cycle as IDTA 02021's motion file (§2.2.2): rows of time, angle, angular velocity
and acceleration at the output, exact between them (``services/aas.py`` writes it)."""

from __future__ import annotations

from collections.abc import Iterable

from actuator_selection.sizing.motion import Piece
from actuator_selection.sizing.units import rpm_to_rad_per_s

MOTION_COLUMNS = (
    ("Time", "s"),
    ("AngularPosition", "rad"),
    ("AngularVelocity", "rad/s"),
    ("AngularAcceleration", "rad/s²"),
)
"""The motion file's columns, idShorts of ``MetadataRotativeMotionFile`` and their units."""


def motion_rows(pieces: Iterable[Piece]) -> list[tuple[float, float, float, float]]:
    """(t [s], θ [rad], ω [rad/s], α [rad/s²]) at the start and end of every piece.

    Within a piece the acceleration is constant or linear (``sizing.motion.Piece``), so
    θ(t) = θ₀ + ω₀·t + α₀·t²/2 + (α₁ − α₀)·t²/6 is exact; where the acceleration jumps
    between pieces the file has two rows at the same time.

    The worked example (Table 516.1) turns 40 rpm·(0.1/2 + 0.1 + 0.1/2) s = 0.8378 rad:

    >>> from actuator_selection.sizing.cycle import Load, SpeedPattern
    >>> from actuator_selection.sizing.motion import pieces_of
    >>> from actuator_selection.sizing.selection import Application
    >>> pattern = SpeedPattern(speed_rpm=40, accel_s=0.1, constant_s=0.1, decel_s=0.1,
    ...                        pause_s=1.0)
    >>> app = Application(pattern=pattern, load=Load(torque_nm=5, inertia_kgm2=1.3))
    >>> rows = motion_rows(pieces_of(app.cycle))
    >>> [round(v, 4) for v in rows[-1]]
    [1.3, 0.8378, 0.0, 0.0]
    """
    rows: list[tuple[float, float, float, float]] = []
    time_s = angle_rad = 0.0
    for p in pieces:
        w0, w1 = rpm_to_rad_per_s(p.start_rpm), rpm_to_rad_per_s(p.end_rpm)
        rows.append((time_s, angle_rad, w0, p.accel_start))
        t = p.duration_s
        angle_rad += w0 * t + p.accel_start * t * t / 2 + (p.accel_end - p.accel_start) * t * t / 6
        time_s += t
        rows.append((time_s, angle_rad, w1, p.accel_end))
    return rows


def motion_csv(rows: Iterable[tuple[float, ...]]) -> bytes:
    """The motion file as IDTA 02021 §2.2.2 defines it: a heading line of ``idShort
    [unit]``, ``;`` between columns, floats with a decimal point (Python's shortest repr,
    so each value reads back exactly)."""
    lines = [";".join(f"{name} [{unit}]" for name, unit in MOTION_COLUMNS)]
    lines += [";".join(repr(float(v)) for v in row) for row in rows]
    return ("\r\n".join(lines) + "\r\n").encode()
