"""The installed Python module against the installed `mvpl` (issue 34): the same image as `mvpl
render` for the same scene, seed and VPLs, arrays of the right shape and dtype, bad input raising
ValueError with the command line's one line, compare() equal to `mvpl compare --json`, Ctrl-C and
a failing progress callback ending a render or a reference.

usage: PYTHONPATH=PREFIX/lib/python3.X/dist-packages python3 test_module.py MVPL_EXE ASSETS_DIR
"""
import json
import os
import signal
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import numpy as np

import mvpl

MVPL = sys.argv[1]
SCENE = os.path.join(sys.argv[2], "cornell-box", "cbox.gltf")
# Tiny: the test must stay cheap (a few seconds on two lavapipe cores).
RENDER = ["--res", "32x32", "--vpls", "64", "--seed", "7"]
KEYWORDS = dict(res=(32, 32), vpls=64, seed=7)


def run_mvpl(*args, cwd=None):
    return subprocess.run([MVPL, *args], capture_output=True, text=True, cwd=cwd)


def cli_error_line(*args):
    """The one line `mvpl ARGS` prints for bad input (exit code 2)."""
    with tempfile.TemporaryDirectory() as folder:
        result = run_mvpl(*args, cwd=folder)
    assert result.returncode == 2, result
    lines = result.stderr.splitlines()
    assert len(lines) == 1, result.stderr
    return lines[0]


class ModuleTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scene = mvpl.load_file(SCENE)
        cls.folder = tempfile.TemporaryDirectory()
        cls.cli_exr = os.path.join(cls.folder.name, "cli.exr")
        result = run_mvpl("render", SCENE, *RENDER, "--quiet", "-o", cls.cli_exr)
        assert result.returncode == 0, result.stderr

    @classmethod
    def tearDownClass(cls):
        cls.folder.cleanup()

    def test_render_equals_the_command_line(self):
        # A render of a fixed VPL count is deterministic for its seed (the chunks, the sub-pixel
        # positions and the CPU estimators' passes are fixed): the same pixels to the bit.
        image = mvpl.render(self.scene, **KEYWORDS)
        self.assertEqual(image.shape, (32, 32, 3))
        self.assertEqual(image.dtype, np.float32)
        self.assertGreater(float(image.mean()), 0.0)
        error = mvpl.compare(image, self.cli_exr)
        self.assertEqual(error["RMSE"], 0.0, error)
        # Another seed gives another image: the comparison can fail.
        other = mvpl.render(self.scene, **dict(KEYWORDS, seed=8))
        self.assertGreater(mvpl.compare(other, self.cli_exr)["RMSE"], 0.0)

    def test_aovs_come_as_a_dict_beside_the_same_image(self):
        image, layers = mvpl.render(self.scene, aovs=("albedo", "normal", "depth", "position"),
                                    **KEYWORDS)
        self.assertEqual(mvpl.compare(image, self.cli_exr)["RMSE"], 0.0)
        self.assertEqual(set(layers), {"albedo", "normal", "depth", "position"})
        for name, channels in (("albedo", 3), ("normal", 3), ("depth", 1), ("position", 3)):
            self.assertEqual(layers[name].shape, (32, 32, channels), name)
            self.assertEqual(layers[name].dtype, np.float32, name)
        # The centre sees the box's back wall; a pixel that sees nothing reports 0 in every AOV
        # (misses count 0 in the average); albedos lie in [0, 1] and normals, averages of unit
        # ones, are no longer than 1.
        self.assertGreater(float(layers["depth"][16, 16, 0]), 0.0)
        missed = layers["depth"][:, :, 0] == 0.0
        self.assertTrue(np.all(layers["albedo"][missed] == 0.0))
        self.assertTrue(np.all(layers["depth"] >= 0.0))
        self.assertTrue(np.all((layers["albedo"] >= 0.0) & (layers["albedo"] <= 1.0)))
        self.assertTrue(np.all(np.linalg.norm(layers["normal"], axis=2) <= 1.0 + 1e-5))
        # One comma-separated string is the same request; a bad name is the CLI's error.
        _, again = mvpl.render(self.scene, aovs="depth", **KEYWORDS)
        np.testing.assert_array_equal(again["depth"], layers["depth"])
        with self.assertRaises(ValueError):
            mvpl.render(self.scene, aovs=("albedo", "shine"), **KEYWORDS)

    def test_compare_is_compare_json(self):
        other = os.path.join(self.folder.name, "other.exr")
        self.assertEqual(run_mvpl("render", SCENE, *RENDER[:-1], "8", "--quiet", "-o",
                                  other).returncode, 0)
        cli = json.loads(run_mvpl("compare", other, self.cli_exr, "--json").stdout)
        self.assertEqual(mvpl.compare(other, self.cli_exr), cli)
        self.assertEqual(set(cli), {"relMSE", "RMSE", "mean_abs", "mean_ratio", "rel_err_p999",
                                    "max_ratio"})

    def test_reference_shape(self):
        image = mvpl.reference(self.scene, spp=1, res=(8, 6), max_depth=2)
        self.assertEqual(image.shape, (6, 8, 3))
        self.assertEqual(image.dtype, np.float32)
        self.assertGreater(float(image.mean()), 0.0)

    def test_reference_equals_the_command_line(self):
        # Traced in chunks sized by the clock, in both: the image does not depend on them.
        exr = os.path.join(self.folder.name, "reference.exr")
        args = ["--res", "16x16", "--spp", "48", "--seed", "3"]
        self.assertEqual(run_mvpl("reference", SCENE, *args, "--quiet", "-o", exr).returncode, 0)
        shares = []
        image, layers = mvpl.reference(self.scene, res=(16, 16), spp=48, seed=3,
                                       aovs=("albedo", "depth"), progress=shares.append)
        self.assertEqual(mvpl.compare(image, exr)["RMSE"], 0.0)
        self.assertGreater(mvpl.compare(mvpl.reference(self.scene, res=(16, 16), spp=48, seed=4),
                                        exr)["RMSE"], 0.0)
        self.assertEqual(shares[-1], 1.0)
        self.assertEqual(shares, sorted(shares))
        self.assertEqual(layers["albedo"].shape, (16, 16, 3))
        self.assertEqual(layers["depth"].shape, (16, 16, 1))
        self.assertGreater(float(layers["depth"][8, 8, 0]), 0.0)
        with self.assertRaises(ValueError):
            mvpl.reference(self.scene, write_every=1)

    def test_ctrl_c_ends_a_reference_after_the_chunk_in_flight(self):
        # A real SIGINT while the tracer runs with the GIL released: KeyboardInterrupt once the
        # chunk in flight (about half a second) is done, where the whole would take hours.
        timer = threading.Timer(0.5, os.kill, (os.getpid(), signal.SIGINT))
        start = time.monotonic()
        timer.start()
        with self.assertRaises(KeyboardInterrupt):
            mvpl.reference(self.scene, res=(8, 8), spp=10**9)
        timer.join()
        self.assertLess(time.monotonic() - start, 30.0)

    def test_bad_input_raises_the_command_lines_line(self):
        cases = [
            (lambda: mvpl.render(self.scene, vpls=0), ["render", SCENE, "--vpls", "0"]),
            (lambda: mvpl.render(self.scene, vpl=3), ["render", SCENE, "--vpl", "3"]),
            (lambda: mvpl.render(self.scene, sampler="gibbs"),
             ["render", SCENE, "--sampler", "gibbs"]),
            (lambda: mvpl.reference(self.scene, spp=0), ["reference", SCENE, "--spp", "0"]),
            (lambda: mvpl.load_file("no-such-scene.gltf"), ["render", "no-such-scene.gltf"]),
        ]
        for call, args in cases:
            with self.subTest(args=args):
                with self.assertRaises(ValueError) as raised:
                    call()
                self.assertEqual(str(raised.exception), cli_error_line(*args))

    def test_progress_reaches_one(self):
        shares = []
        mvpl.render(self.scene, progress=shares.append, **KEYWORDS)
        self.assertEqual(shares[-1], 1.0)
        self.assertEqual(shares, sorted(shares))

    def test_ctrl_c_and_a_failing_callback_end_the_render(self):
        def interrupt(done):
            os.kill(os.getpid(), signal.SIGINT)  # as Ctrl-C: Python's handler sets a flag

        with self.assertRaises(KeyboardInterrupt):
            mvpl.render(self.scene, progress=interrupt, **KEYWORDS)

        def fail(done):
            raise RuntimeError("from the callback")

        with self.assertRaisesRegex(RuntimeError, "from the callback"):
            mvpl.render(self.scene, progress=fail, **KEYWORDS)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
