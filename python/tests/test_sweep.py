"""`python3 -m ontile.sweep` on a LocalCluster of 2 worker processes writes the same table, byte
for byte, as the serial run: 2 pipelines x 2 tile sizes of the demo at 160x90."""
import json
import os
import subprocess
import sys
import unittest

from ontile_test_env import DEMO, needs_module, ontile, output_dir

CONFIG = {"scenes": [os.path.basename(DEMO)], "pipelines": ["cartoon", "lambert"], "sizes": [[160, 90]],
          "threads": 1, "options": {"render_graph": "off"}, "grid": {"tile": [32, 16]}}


def sweep(*args):
    return subprocess.run([sys.executable, "-m", "ontile.sweep"] + list(args), capture_output=True, text=True)


@needs_module
class SweepOnDask(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.out = output_dir("sweep")
        # The config sits beside the scene: scene paths are relative to the config's folder.
        cls.config = os.path.join(cls.out, "grid.json")
        config = dict(CONFIG, scenes=[os.path.relpath(DEMO, cls.out)])
        with open(cls.config, "w", encoding="utf-8") as f:
            json.dump(config, f)

    def read(self, name):
        with open(os.path.join(self.out, name), encoding="utf-8") as f:
            return f.read()

    def test_local_cluster_table_equals_serial(self):
        serial = sweep(self.config, "--serial", "--csv", os.path.join(self.out, "serial.csv"),
                       "--json", os.path.join(self.out, "serial.json"))
        self.assertEqual(serial.returncode, 0, serial.stderr)
        dask = sweep(self.config, "--workers", "2", "--csv", os.path.join(self.out, "dask.csv"),
                     "--json", os.path.join(self.out, "dask.json"))
        self.assertEqual(dask.returncode, 0, dask.stderr)
        self.assertEqual(self.read("dask.csv"), self.read("serial.csv"))
        self.assertEqual(self.read("dask.json"), self.read("serial.json"))

        table = json.loads(self.read("serial.json"))
        rows = table["rows"]
        self.assertEqual([(r["pipeline"], r["tile"]) for r in rows],
                         [("cartoon", 16), ("cartoon", 32), ("lambert", 16), ("lambert", 32)])
        self.assertIn("image_sha256", table["columns"])
        self.assertTrue(any(c.startswith("bytes.") for c in table["columns"]), table["columns"])
        # Tile size changes the traffic, never the image.
        self.assertEqual(rows[0]["image_sha256"], rows[1]["image_sha256"])
        self.assertNotEqual(rows[0]["bytes_read"] + rows[0]["bytes_written"],
                            rows[1]["bytes_read"] + rows[1]["bytes_written"])
        # Each row is what ontile.render reports for that configuration.
        single = ontile.render(DEMO, pipeline="lambert", size=(160, 90), threads=1, options={"tile": 32})
        self.assertEqual(rows[3]["bytes_read"], single.report["frame"]["bytes_read"])

    def test_bad_config_is_one_error_line_and_exit_2(self):
        bad = os.path.join(self.out, "bad.json")
        with open(bad, "w", encoding="utf-8") as f:
            json.dump(dict(CONFIG, pipelines="lambert"), f)
        result = sweep(bad, "--serial")
        self.assertEqual(result.returncode, 2)
        self.assertRegex(result.stderr, r"^error: .*bad\.json: 'pipelines': expected a non-empty list")
        self.assertEqual(result.stderr.count("\n"), 1)
        self.assertEqual(result.stdout, "")

    def test_bad_option_in_grid_is_exit_2(self):
        bad = os.path.join(self.out, "bad-option.json")
        with open(bad, "w", encoding="utf-8") as f:
            json.dump(dict(CONFIG, scenes=[os.path.relpath(DEMO, self.out)], grid={"tile": [5]}), f)
        result = sweep(bad, "--serial")
        self.assertEqual(result.returncode, 2)
        self.assertIn("options['tile']", result.stderr)


if __name__ == "__main__":
    unittest.main()
