"""Reference formulas the validation cases and the study are judged against, in one place.

Every formula cites its source (paper by name).
"""
import math
import os

# Sangani & Acrivos 1982, Eq. 60 / Table 1: K = sum_s alpha_s chi^s, chi = (phi / (pi/6))^(1/3).
_SA_ALPHA = [
    1.000000, 1.418649, 2.012564, 2.331523, 2.564809, 2.584787, 2.873609, 3.340163,
    3.536763, 3.504092, 3.253622, 2.689757, 2.037769, 1.809341, 1.877347, 1.534685,
    0.9034708, 0.2857896, -0.5512626, -1.278724, 1.013350, 5.492491, 4.615388,
    -0.5736023, -2.865924, -4.709215, -6.870076, 0.1455304, 12.51891, 9.742811, -5.566269,
]


def sangani_acrivos_k(phi):
    """Dimensionless drag K = F / (6 pi mu a U) on a simple cubic array (Stokes flow)."""
    chi = (phi / (math.pi / 6.0)) ** (1.0 / 3.0)
    return sum(a * chi**s for s, a in enumerate(_SA_ALPHA))


def hasimoto_k(phi):
    """Hasimoto 1959 expansion for the simple cubic array; a few percent up to phi ~ 0.3."""
    c = phi ** (1.0 / 3.0)
    return 1.0 / (1.0 - 1.7601 * c + phi - 1.5593 * phi**2 + 3.9799 * phi ** (8.0 / 3.0)
                  - 3.0734 * phi ** (10.0 / 3.0))


def periodic_sphere_mobility_k(a_over_l):
    """Single sphere in a periodic cube: F / (6 pi mu a U) (Hasimoto's correction)."""
    r = a_over_l
    return 1.0 / (1.0 - 2.837297 * r + (4.0 * math.pi / 3.0) * r**3 - 27.4 * r**6)


def haider_levenspiel_velocity(d_v, sphericity, rho_f, rho_s, mu, g=9.81):
    """Terminal velocity of a non-spherical particle, Haider & Levenspiel 1989 (0.5 <= Phi <= 1)."""
    d_star = d_v * (g * rho_f * (rho_s - rho_f) / mu**2) ** (1.0 / 3.0)
    u_star = 1.0 / (18.0 / d_star**2 + (2.3348 - 1.7439 * sphericity) / math.sqrt(d_star))
    return u_star * (g * mu * (rho_s - rho_f) / rho_f**2) ** (1.0 / 3.0)


def cube_volume_equivalent_diameter(a):
    return a * (6.0 / math.pi) ** (1.0 / 3.0)


CUBE_SPHERICITY = (math.pi / 6.0) ** (1.0 / 3.0)


def richardson_zaki_exponent(re):
    """Richardson & Zaki 1954 exponent n(Re), Re of the single body at its terminal velocity."""
    if re < 0.2:
        return 4.65
    if re < 1.0:
        return 4.35 * re**-0.03
    if re < 500.0:
        return 4.45 * re**-0.1
    return 2.39


def garside_al_dibouni_exponent(re):
    """Garside & Al-Dibouni 1977: n = (5.1 + 0.27 Re^0.9) / (1 + 0.1 Re^0.9), smooth in Re."""
    return (5.1 + 0.27 * re**0.9) / (1.0 + 0.1 * re**0.9)


def rowe_exponent(re):
    """Rowe 1987: n = (4.7 + 0.41 Re^0.75) / (1 + 0.175 Re^0.75), smooth in Re."""
    return (4.7 + 0.41 * re**0.75) / (1.0 + 0.175 * re**0.75)


EXPONENTS = {"richardson-zaki": richardson_zaki_exponent,
             "garside-al-dibouni": garside_al_dibouni_exponent, "rowe": rowe_exponent}


def richardson_zaki(phi, re, exponent="richardson-zaki"):
    """Hindered settling velocity ratio u / u_T = (1 - phi)^n, n(Re) by the named correlation."""
    return (1.0 - phi) ** EXPONENTS[exponent](re)


# Yin & Koch 2007 (Phys. Fluids 19, 093302), lattice-Boltzmann simulations of random sphere
# suspensions at finite Reynolds number: their fits U / U_t = k (1 - phi)^n at the single-sphere
# Reynolds number Re_t.
_YIN_KOCH = ((1.02, 0.92, 4.2), (1.83, 0.90, 4.1), (5.00, 0.86, 4.0), (9.98, 0.86, 3.8),
             (20.0, 0.88, 3.6))


def yin_koch_fit(re):
    """(k, n) of Yin & Koch's fit at Re_t, interpolated linearly in log Re between their five
    Reynolds numbers (1.02-20); outside that range the nearest end."""
    res = [r for r, _, _ in _YIN_KOCH]
    x = min(max(math.log(re), math.log(res[0])), math.log(res[-1]))
    for (r0, k0, n0), (r1, k1, n1) in zip(_YIN_KOCH, _YIN_KOCH[1:]):
        if x <= math.log(r1):
            w = (x - math.log(r0)) / (math.log(r1) - math.log(r0))
            return k0 + w * (k1 - k0), n0 + w * (n1 - n0)
    return _YIN_KOCH[-1][1], _YIN_KOCH[-1][2]


def yin_koch_bracket(re):
    """Yin & Koch's published (Re_t, k, n) next to Re on either side (one row at or beyond an
    end of their range)."""
    below = [row for row in _YIN_KOCH if row[0] <= re]
    above = [row for row in _YIN_KOCH if row[0] >= re]
    return list(dict.fromkeys(([below[-1]] if below else []) + ([above[0]] if above else [])))


def yin_koch(phi, re):
    """U / U_t = k (1 - phi)^n with Yin & Koch's (k, n) at Re_t (yin_koch_fit)."""
    k, n = yin_koch_fit(re)
    return k * (1.0 - phi) ** n


def batchelor(phi):
    """Batchelor 1972, dilute random suspension of spheres in Stokes flow: u/u_T = 1 - 6.55 phi."""
    return 1.0 - 6.55 * phi


def schiller_naumann_cd(re):
    """Drag coefficient of a sphere, Schiller & Naumann 1933 (Re < 800)."""
    return 24.0 / re * (1.0 + 0.15 * re**0.687)


def sphere_terminal_velocity(d, rho_p, rho_f, mu, g=9.81):
    """Terminal velocity of a sphere with the Schiller-Naumann drag: solves
    (pi/6) d^3 (rho_p - rho_f) g = Cd(Re) (pi/8) rho_f u^2 d^2 for u by bisection."""
    def excess(u):
        re = rho_f * u * d / mu
        return (math.pi / 6) * d**3 * (rho_p - rho_f) * g - \
            schiller_naumann_cd(re) * (math.pi / 8) * rho_f * u * u * d * d
    lo, hi = 1e-12, (rho_p - rho_f) * g * d * d / (18 * mu)  # Stokes is an upper bound
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if excess(mid) > 0 else (lo, mid)
    return 0.5 * (lo + hi)


# ten Cate et al. 2002: peak settling speed u_max (m/s) in the closed box.
TEN_CATE = {
    "E1": {"rho_f": 970.0, "mu": 0.373, "u_inf": 0.038, "u_max": 0.0360},
    "E4": {"rho_f": 960.0, "mu": 0.058, "u_inf": 0.128, "u_max": 0.1222},
}

# Single sphere terminal velocity for the hindered-settling study (Rettinger & Rüde 2017).
SPHERE_TERMINAL_VELOCITY = 0.048  # m/s, d = 0.35 mm, rho_p = 2500, rho_f = 1000, mu = 1e-3


CURVES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "reference_curves")


def reference_curve(name):
    """A measured curve from reference_curves/NAME.csv (its header says where it comes from):
    two arrays, the first column and the second."""
    with open(os.path.join(CURVES, name + ".csv")) as f:
        rows = [line.split(",") for line in f if line.strip() and not line.startswith("#")][1:]
    return [float(r[0]) for r in rows], [float(r[1]) for r in rows]
