"""Reference values the validation cases are judged against.

Every formula cites its source; the numbers are those of shared/reference/reference-data.md.
"""
import math

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
    """Richardson & Zaki 1954 exponent n(Re)."""
    if re < 0.2:
        return 4.65
    if re < 1.0:
        return 4.35 * re**-0.03
    if re < 500.0:
        return 4.45 * re**-0.1
    return 2.39


def richardson_zaki(phi, re):
    """Hindered settling velocity ratio u / u_T = (1 - phi)^n."""
    return (1.0 - phi) ** richardson_zaki_exponent(re)


# ten Cate et al. 2002: peak settling speed u_max (m/s) in the closed box.
TEN_CATE = {
    "E1": {"rho_f": 970.0, "mu": 0.373, "u_inf": 0.038, "u_max": 0.0360},
    "E4": {"rho_f": 960.0, "mu": 0.058, "u_inf": 0.128, "u_max": 0.1222},
}

# Single sphere terminal velocity for the hindered-settling study (Rettinger & Rüde 2017).
SPHERE_TERMINAL_VELOCITY = 0.048  # m/s, d = 0.35 mm, rho_p = 2500, rho_f = 1000, mu = 1e-3
