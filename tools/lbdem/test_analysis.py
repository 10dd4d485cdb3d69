"""Each analysis function on synthetic data with a known answer (ctest tools_lbdem_py)."""
import unittest

import numpy as np

from lbdem import analysis, geometry, references


class SteadyStateAndErrorBar(unittest.TestCase):
    def test_mser_skips_the_transient(self):
        # Relaxation u(t) = -1 + exp(-t / 20) plus noise: the transient is gone (to the noise,
        # 0.01) after ~20 ln(100) = 92 samples; MSER must cut between 40 and 200 samples.
        rng = np.random.default_rng(1)
        t = np.arange(2000)
        x = -1 + np.exp(-t / 20.0) + 0.01 * rng.standard_normal(len(t))
        d = analysis.mser_start(x)
        self.assertGreater(d, 40)
        self.assertLess(d, 200)
        self.assertAlmostEqual(x[d:].mean(), -1.0, delta=0.002)

    def test_mser_keeps_a_stationary_series(self):
        rng = np.random.default_rng(2)
        self.assertLess(analysis.mser_start(rng.standard_normal(1000)), 500)

    def test_block_average_of_an_ar1_series(self):
        # AR(1) x_k = rho x_{k-1} + e_k: the standard error of the mean of n samples is
        # sigma_x / sqrt(n) * sqrt((1 + rho) / (1 - rho)) for n >> correlation time.
        rng = np.random.default_rng(3)
        rho, n = 0.9, 2**16
        e = rng.standard_normal(n)
        x = np.empty(n)
        x[0] = e[0] / np.sqrt(1 - rho**2)
        for k in range(1, n):
            x[k] = rho * x[k - 1] + e[k]
        sigma = 1 / np.sqrt(1 - rho**2)
        exact = sigma / np.sqrt(n) * np.sqrt((1 + rho) / (1 - rho))
        mean, err = analysis.block_average(x)
        self.assertAlmostEqual(err / exact, 1.0, delta=0.3)
        naive = x.std() / np.sqrt(n)
        self.assertGreater(err, 3 * naive)  # the naive error bar is sqrt(19) = 4.4 too small


class ZeroVolumeFluxFrame(unittest.TestCase):
    def test_settling_and_slip_velocity(self):
        # phi = 0.3, bodies at -0.02 m/s, fluid at +0.003 m/s: j = 0.3 (-0.02) + 0.7 (0.003)
        # = -0.0039 (what the fluid series reports as mean_uz); V = u_p - j = -0.0161 and the slip
        # u_p - u_f = -0.023 = V / (1 - phi).
        phi, up, uf = 0.3, -0.02, 0.003
        j = phi * up + (1 - phi) * uf
        v = analysis.settling_velocity(up, j)
        self.assertAlmostEqual(float(v), -0.0161, places=12)
        self.assertAlmostEqual(float(analysis.slip_velocity(v, phi)), up - uf, places=12)


class HinderedSettlingFit(unittest.TestCase):
    def test_recovers_k_and_n_with_an_error_that_covers_the_noise(self):
        rng = np.random.default_rng(5)
        phi = np.array([0.05, 0.1, 0.2, 0.3, 0.4])
        noise = 0.01
        u = 0.88 * (1 - phi) ** 3.6 * (1 + noise * rng.standard_normal(phi.size))
        f = analysis.fit_hindered_settling(phi, u, noise * u)
        self.assertLess(abs(f["k"] - 0.88), 3 * f["k_error"] + 1e-12)
        self.assertLess(abs(f["n"] - 3.6), 3 * f["n_error"] + 1e-12)
        self.assertLess(f["n_error"], 0.3)
        exact = analysis.fit_hindered_settling(phi, 0.9 * (1 - phi) ** 4.0)
        self.assertAlmostEqual(exact["k"], 0.9, places=12)
        self.assertAlmostEqual(exact["n"], 4.0, places=12)
        self.assertLess(exact["rms_relative_residual"], 1e-12)

    def test_yin_koch_table_and_interpolation(self):
        self.assertEqual(references.yin_koch_fit(20.0), (0.88, 3.6))
        k, n = references.yin_koch_fit(1.02)
        self.assertAlmostEqual(k, 0.92)
        self.assertAlmostEqual(n, 4.2)
        k, n = references.yin_koch_fit(16.8)  # the study's Re: between 9.98 and 20
        self.assertTrue(0.86 < k < 0.88 and 3.6 < n < 3.8)
        self.assertEqual(references.yin_koch_fit(100.0), (0.88, 3.6))  # clamped
        self.assertAlmostEqual(references.yin_koch(0.3, 20.0), 0.88 * 0.7**3.6)
        self.assertEqual(references.yin_koch_bracket(16.8), [(9.98, 0.86, 3.8), (20.0, 0.88, 3.6)])
        self.assertEqual(references.yin_koch_bracket(20.0), [(20.0, 0.88, 3.6)])
        self.assertEqual(references.yin_koch_bracket(0.5), [(1.02, 0.92, 4.2)])


class Structure(unittest.TestCase):
    box = np.array([1.0, 1.0, 1.0])

    def test_ideal_gas_has_g_equal_one(self):
        rng = np.random.default_rng(4)
        x = rng.random((20, 400, 3))
        r, g = analysis.radial_distribution(x, self.box, bins=10)
        # 20 x 79800 pairs; the smallest shell (r < 0.05) still holds ~420 pairs: 5 % noise.
        np.testing.assert_allclose(g, 1.0, atol=0.15)
        self.assertAlmostEqual(g[3:].mean(), 1.0, delta=0.02)

    def test_simple_cubic_lattice_peaks_at_the_spacing(self):
        n, a = 5, 0.2
        x = np.stack(np.meshgrid(*[np.arange(n) * a] * 3, indexing="ij"), -1).reshape(-1, 3)
        r, g = analysis.radial_distribution(x, self.box, r_max=0.5, bins=48)  # a inside a bin
        first = np.nonzero(g)[0][0]  # minimum image: no pair closer than a, 6 neighbours at a
        self.assertAlmostEqual(r[first], a, delta=0.01)
        w = 0.5 / 48
        shell = 4 / 3 * np.pi * ((r[first] + w / 2) ** 3 - (r[first] - w / 2) ** 3)
        self.assertAlmostEqual(g[first], 6 * 0.5 * n**3 / (0.5 * n**3 * (n**3 - 1) * shell), 6)

    def test_near_pairs_of_an_ideal_gas_and_of_a_lattice(self):
        # Random points: the mean g below r_near is 1 within its counting noise. A simple cubic
        # lattice of spacing 1/4 has no pair closer than the spacing and 6 neighbours at it.
        rng = np.random.default_rng(3)
        x = rng.random((200, 64, 3))
        series = analysis.near_pair_series(x, self.box, 0.3)
        self.assertEqual(series.shape, (200,))
        self.assertAlmostEqual(series.mean(), 1.0, delta=0.05)
        g = (np.arange(4) + 0.5) / 4
        lattice = np.stack(np.meshgrid(g, g, g, indexing="ij"), -1).reshape(-1, 3)
        self.assertEqual(analysis.near_pair_series(lattice, self.box, 0.24)[0], 0.0)
        ideal = 0.5 * 64 * 63 * 4 / 3 * np.pi * 0.26**3
        self.assertAlmostEqual(analysis.near_pair_series(lattice, self.box, 0.26)[0],
                               64 * 6 / 2 / ideal, places=12)

    def test_near_pairs_find_when_the_structure_settles(self):
        # Bodies drawn at random (g = 1) that pair up from snapshot 120 on: the steady start of
        # the series (MSER) lies at the change, not before it.
        rng = np.random.default_rng(4)
        x = rng.random((300, 64, 3))
        x[120:, 32:] = x[120:, :32] + 0.05
        series = analysis.near_pair_series(x, self.box, 0.1)
        start = analysis.mser_start(series)
        self.assertGreaterEqual(start, 120)
        self.assertLess(start, 130)
        self.assertGreater(series[120:].mean(), 3 * series[:120].mean())

    def test_velocity_correlation_of_a_plane_wave(self):
        # v_z = cos(k x) at uniformly random points: <cos(k x_i) cos(k x_j)> over pairs at
        # distance r in random directions is sin(kr) / (2 kr), <v^2> = 1/2: C(r) = sin(kr) / (kr).
        rng = np.random.default_rng(5)
        k = 2 * np.pi
        x = rng.random((20, 300, 3))
        vz = np.cos(k * x[..., 0])
        r, c = analysis.velocity_correlation(x, vz, self.box, bins=10)
        np.testing.assert_allclose(c, np.sin(k * r) / (k * r), atol=0.06)

    def test_velocity_correlation_of_independent_velocities_is_zero(self):
        rng = np.random.default_rng(6)
        x = rng.random((20, 300, 3))
        r, c = analysis.velocity_correlation(x, rng.standard_normal((20, 300)), self.box, bins=10)
        np.testing.assert_allclose(c, 0.0, atol=0.05)


class Autocorrelation(unittest.TestCase):
    def test_ornstein_uhlenbeck_decays_exponentially(self):
        # Exact OU update with rate gamma: v_{k+1} = v_k a + sqrt(1 - a^2) xi, a = e^{-gamma dt};
        # C(t) = exp(-gamma t).
        rng = np.random.default_rng(7)
        steps, bodies, a = 4000, 50, np.exp(-0.1)
        v = np.empty((steps, bodies, 2))
        v[0] = rng.standard_normal((bodies, 2))
        for k in range(1, steps):
            v[k] = a * v[k - 1] + np.sqrt(1 - a * a) * rng.standard_normal((bodies, 2))
        c = analysis.vacf(v, max_lag=30, subtract_mean=False)
        np.testing.assert_allclose(c, a ** np.arange(31), atol=0.02)
        # Removing the body mean (1/N of the variance) changes C by O(1/N) only.
        np.testing.assert_allclose(analysis.vacf(v, max_lag=30), c, atol=0.03)


class Orientation(unittest.TestCase):
    def test_random_rotations_give_uniform_cosines(self):
        q = geometry.random_quaternions(np.random.default_rng(8), 20000)
        c = analysis.axes_against_gravity(q)
        self.assertAlmostEqual(c.mean(), 0.5, delta=0.01)
        hist = np.histogram(c, bins=5, range=(0, 1))[0] / c.size
        np.testing.assert_allclose(hist, 0.2, atol=0.01)

    def test_face_down_cube(self):
        c = analysis.axes_against_gravity(np.array([1.0, 0, 0, 0]))
        np.testing.assert_allclose(c, [0, 0, 1])

    def test_face_angles_of_touching_cubes(self):
        box = np.array([10.0, 10.0, 10.0])
        x = np.array([[1.0, 1.0, 1.0], [2.0, 1.0, 1.0], [5.0, 5.0, 5.0]])
        # Two aligned cubes face to face (gap 0) and a far one: one pair, angle 0.
        q = np.array([[1.0, 0, 0, 0]] * 3)
        np.testing.assert_allclose(analysis.contact_face_angles(x, q, box, 1.0, 0.01), [0.0],
                                   atol=1e-6)
        # Turn the second one by 30 degrees about z and move it so its edge touches: the most
        # nearly parallel faces are the z faces (angle 0); about a tilted axis no pair is parallel.
        h = np.radians(30) / 2
        q[1] = [np.cos(h), 0, 0, np.sin(h)]
        x[1, 0] = 1.0 + 0.5 + 0.5 * (np.cos(np.radians(30)) + np.sin(np.radians(30)))
        np.testing.assert_allclose(analysis.contact_face_angles(x, q, box, 1.0, 0.01), [0.0],
                                   atol=1e-6)
        axis = np.array([1.0, 1.0, 1.0]) / np.sqrt(3)
        h = np.radians(20) / 2
        q[1] = np.concatenate([[np.cos(h)], np.sin(h) * axis])
        x[1, 0] = 2.2  # near the first cube; counted as touching with gap = their separation
        sep = geometry.box_separation(x[1] - x[0], geometry.rotation_matrices(q[0])[None],
                                      geometry.rotation_matrices(q[1])[None], np.full(3, 0.5),
                                      np.full(3, 0.5))
        angles = analysis.contact_face_angles(x, q, box, 1.0, sep[0] + 1e-9)
        self.assertEqual(len(angles), 1)
        self.assertGreater(angles[0], 5.0)


class BoxSeparation(unittest.TestCase):
    def test_axis_aligned_and_rotated(self):
        eye = np.eye(3)[None]
        half = np.full(3, 0.5)
        # Aligned unit cubes 1.25 apart along x: gap 0.25 exactly.
        self.assertAlmostEqual(
            float(geometry.box_separation(np.array([[1.25, 0, 0]]), eye, eye, half, half)[0]),
            0.25)
        # One turned 45 degrees about z reaches sqrt(2)/2 along x: touching at 0.5 + 0.7071.
        h = np.pi / 8
        r = geometry.rotation_matrices(np.array([np.cos(h), 0, 0, np.sin(h)]))[None]
        for dx, overlap in [(1.2, True), (1.22, False)]:
            gap = geometry.box_separation(np.array([[dx, 0, 0]]), eye, r, half, half)[0]
            self.assertEqual(gap <= 0, overlap, dx)


class CurveDifference(unittest.TestCase):
    """u(t) against a digitized curve: a known offset, a known time shift."""

    def setUp(self):
        self.t = np.linspace(0.0, 2.0, 2001)
        self.u = 0.04 * (1 - np.exp(-self.t / 0.3))
        self.t_ref = np.linspace(0.1, 1.9, 25)

    def test_a_uniform_offset_is_its_size_in_units_of_the_peak(self):
        u_ref = 0.04 * (1 - np.exp(-self.t_ref / 0.3)) - 0.0008
        d = analysis.curve_difference(self.t, self.u, self.t_ref, u_ref)
        peak = np.max(np.abs(u_ref))
        self.assertEqual(d["n"], 25)
        self.assertAlmostEqual(d["rms"], 0.0008 / peak, places=6)
        self.assertAlmostEqual(d["largest"], 0.0008 / peak, places=6)

    def test_a_time_shift_is_found_and_removed(self):
        # The reference's clock runs 40 ms late: moving its origin by -40 ms removes the
        # difference (to the interpolation error of the computed curve).
        u_ref = 0.04 * (1 - np.exp(-(self.t_ref - 0.04) / 0.3))
        d = analysis.curve_difference(self.t, self.u, self.t_ref, u_ref)
        self.assertGreater(d["rms"], 0.01)
        self.assertAlmostEqual(d["shift"], -0.04, places=6)
        self.assertLess(d["rms_shifted"], 1e-5)

    def test_only_points_inside_the_run_are_compared(self):
        d = analysis.curve_difference(self.t[:1001], self.u[:1001], self.t_ref,
                                      0.04 * (1 - np.exp(-self.t_ref / 0.3)))
        self.assertEqual(d["n"], int(np.sum(self.t_ref <= 1.0)))
        self.assertLess(d["rms"], 1e-6)


class SmoothedPeak(unittest.TestCase):
    """The peak of a speed that rippled at its lattice-crossing frequency."""

    def setUp(self):
        self.t = np.linspace(0.0, 3.0, 301)                      # 0.01 s samples
        self.base = 0.036 * np.exp(-(((self.t - 1.5) / 1.0) ** 2))  # a smooth hump, peak 0.036

    def test_the_ripple_crest_is_averaged_out(self):
        period = 0.07
        u = self.base + 0.0005 * np.sin(2 * np.pi * self.t / period + 0.3)
        self.assertGreater(u.max(), 0.036 + 0.0003)             # the raw maximum: the crest
        k, t_peak, peak, smooth, n = analysis.smoothed_peak(self.t, u, period)
        self.assertEqual(n, 7)
        self.assertAlmostEqual(peak, 0.036, delta=0.036 * 2e-3)
        self.assertAlmostEqual(t_peak, 1.5, delta=0.05)
        self.assertEqual(len(smooth), len(u))

    def test_a_smooth_series_keeps_its_peak(self):
        k, t_peak, peak, _, _ = analysis.smoothed_peak(self.t, self.base, 0.07)
        self.assertAlmostEqual(peak, 0.036, delta=0.036 * 5e-4)
        self.assertAlmostEqual(t_peak, 1.5, places=6)

    def test_a_period_below_two_samples_leaves_the_series(self):
        u = self.base + 0.0005 * np.sin(2 * np.pi * self.t / 0.005)
        k, _, peak, smooth, n = analysis.smoothed_peak(self.t, u, 0.005)
        self.assertEqual(n, 1)
        self.assertEqual(peak, u.max())
        self.assertTrue(np.array_equal(smooth, u))


class VerletOrbitalGain(unittest.TestCase):
    def test_constant_force_leaves_the_impulse_moment_and_the_verlet_term(self):
        # One body under a constant force, stepped exactly as velocity Verlet moves it: the
        # orbital angular momentum changes by the impulse's moment at x^n plus the returned term.
        m, dt, f = 2.0, 0.1, np.array([0.3, -0.2, 0.5])
        x, v = [np.array([0.2, 0.4, 0.1])], [np.array([1.0, 0.5, -0.25])]
        impulse_moment = np.zeros(3)
        for _ in range(6):
            impulse_moment += np.cross(x[-1], f * dt)
            x.append(x[-1] + v[-1] * dt + f * dt * dt / (2 * m))
            v.append(v[-1] + f * dt / m)
        x, v = np.array(x)[:, None, :], np.array(v)[:, None, :]
        gain = analysis.verlet_orbital_gain(x, v, [m], [10.0, 10.0, 10.0])
        orbital = np.cross(x[:, 0], m * v[:, 0])
        np.testing.assert_allclose(orbital[-1] - orbital[0] - impulse_moment, gain[-1],
                                   rtol=1e-12, atol=1e-15)
        self.assertGreater(np.abs(gain[-1]).max(), 1e-4)  # not zero: v x F != 0 here

    def test_a_move_across_the_periodic_face_counts_as_the_short_move(self):
        x = np.array([[[9.95, 0.0, 0.0]], [[0.05, 0.0, 0.0]]])
        v = np.array([[[1.0, 1.0, 0.0]], [[1.0, 1.0, 0.0]]])
        gain = analysis.verlet_orbital_gain(x, v, [1.0], [10.0, 10.0, 10.0])
        np.testing.assert_allclose(gain[-1], [0.0, 0.0, 0.1], atol=1e-12)


class KnownOff(unittest.TestCase):
    """A known-off case passes only while it stays off, inside its recorded band."""

    def test_off_inside_the_band_passes(self):
        ok, verdict = analysis.judge_known_off(-0.0336, 0.03, (-0.040, -0.030))
        self.assertTrue(ok)
        self.assertIn("known off: -3.36 %", verdict)

    def test_within_the_tolerance_fails(self):
        ok, verdict = analysis.judge_known_off(-0.029, 0.03, (-0.040, -0.025))
        self.assertFalse(ok)
        self.assertIn("no longer off", verdict)

    def test_outside_the_band_fails(self):
        for e in (-0.05, 0.035):
            ok, verdict = analysis.judge_known_off(e, 0.03, (-0.040, -0.030))
            self.assertFalse(ok)
            self.assertIn("outside its recorded band", verdict)


if __name__ == "__main__":
    unittest.main()
