"""The stability study's verdict on a case (ctest tools_lbdem_py): the expected outcome alone
is not enough; a computed error must stay within its bound and a refusal or diagnosis must
name its cause."""
import unittest

from lbdem import stability


def row(case, outcome, error=None, message=""):
    return {"case": case, "expected": stability.CASES[case][0], "outcome": outcome,
            "error": error, "message": message}


class Judge(unittest.TestCase):
    def test_every_bound_and_message_names_a_case(self):
        self.assertLessEqual(set(stability.BOUNDS) | set(stability.MESSAGES),
                             set(stability.CASES))

    def test_every_case_with_a_number_has_a_bound(self):
        numeric = {"vs_base", "fluid_validation", "terminal_hl", "overlap", "pair", "travel"}
        for name, (expected, _, measure) in stability.CASES.items():
            if expected == "runs" and measure in numeric:
                self.assertIn(name, stability.BOUNDS, name)

    def test_within_the_bound_passes(self):
        self.assertEqual(stability.judge(row("tau_0p51", "runs", 0.19)), (True, ""))

    def test_above_the_bound_fails(self):
        ok, why = stability.judge(row("tau_0p51", "runs", 0.5))
        self.assertFalse(ok)
        self.assertIn("above its bound", why)

    def test_a_missing_error_fails(self):
        ok, why = stability.judge(row("mach_0p1", "runs", None))
        self.assertFalse(ok)
        self.assertIn("no error computed", why)

    def test_a_diagnosis_must_name_its_cause(self):
        self.assertTrue(stability.judge(row("mach_0p4", "diagnosed", None,
                                            "exit 3: fluid is unstable: Mach 0.36"))[0])
        ok, why = stability.judge(row("mach_0p4", "diagnosed", None, "exit 1: MPI_ABORT"))
        self.assertFalse(ok)

    def test_the_wrong_outcome_fails(self):
        self.assertFalse(stability.judge(row("tau_0p501", "runs"))[0])


if __name__ == "__main__":
    unittest.main()
