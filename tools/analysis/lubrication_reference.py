"""Squeeze-flow references for the lubrication validation (docs/lubrication.md).

Forces are given as lambda = F / (6 pi mu a U), U the speed of each body.

* brenner_wall(h, a): exact Stokes resistance of a sphere moving normal to a plane wall at gap h
  (Brenner 1961, bispherical coordinates; cosh(alpha) = 1 + h / a).
* brenner_pair(h, a): the same for two equal spheres approaching each other, each at U
  (Brenner 1961 / Maude 1961; cosh(alpha) = 1 + h / (2a)).
* correction(...): the sub-grid correction dem_app applies, written from the same equations as
  dem_app/lubrication/lubrication_law.hpp (Jeffrey & Onishi 1984 singular terms, minus their value at h_c,
  saturated at h_min), to add it to the lattice force recorded for a body whose motion is
  prescribed.
"""
import math


def _series(alpha, term):
    s, n = 0.0, 1
    while (2 * n + 1) * alpha < 600:  # beyond, every further term is below 1e-200
        t = term(n, 2 * n + 1)
        s += t
        if n > 5 and abs(t) < 1e-15 * abs(s):
            break
        n += 1
    return 4.0 / 3.0 * math.sinh(alpha) * s


def brenner_wall(h, a):
    al = math.acosh(1 + h / a)
    return _series(al, lambda n, k: n * (n + 1) / ((2 * n - 1) * (2 * n + 3)) * (
        (2 * math.sinh(k * al) + k * math.sinh(2 * al)) /
        (4 * math.sinh((n + 0.5) * al) ** 2 - k * k * math.sinh(al) ** 2) - 1))


def brenner_pair(h, a):
    al = math.acosh(1 + h / (2 * a))
    return _series(al, lambda n, k: n * (n + 1) / ((2 * n - 1) * (2 * n + 3)) * (
        (4 * math.cosh((n + 0.5) * al) ** 2 + k * k * math.sinh(al) ** 2) /
        (2 * math.sinh(k * al) - k * math.sinh(2 * al)) - 1))


def squeeze_coefficients(a1, a2):
    """g1, g2 of the singular terms; a2 = None for a plane wall."""
    if a2 is None:
        return 1.0, 0.2
    b = a2 / a1
    return b * b / (1 + b) ** 2, b * (1 + 7 * b + b * b) / (5 * (1 + b) ** 3)


def correction(h, a, h_c, h_min, wall):
    """The correction's force on one body in units of 6 pi mu a U (U: each body's speed); zero
    at and beyond h_c and once the surfaces touch (h <= 0), like dem_app's."""
    if h >= h_c or h <= 0:
        return 0.0
    g1, g2 = squeeze_coefficients(a, None if wall else a)
    lam = lambda x: g1 * a / x + g2 * math.log(a / x)  # noqa: E731
    relative = 1.0 if wall else 2.0  # two spheres: the relative speed is 2U
    return relative * (lam(max(h, h_min)) - lam(h_c))
