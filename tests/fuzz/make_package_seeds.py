#!/usr/bin/python3
"""Writes the seed inputs of the package fuzz targets (nothing from ../shared/data):
corpus/manifest/  manifests: a valid one, and ones with a bad digest, a climbing name, a newer version;
corpus/package/   packages: one thespis-cli exported (a scenario naming a BVH file), one made here,
                  and ones a hostile tool might make (a climbing name, a link, a name twice).
Needs thespis-cli: THESPIS_CLI=build/app/cli/thespis-cli python3 tests/fuzz/make_package_seeds.py"""

import hashlib
import json
import os
import subprocess
import tempfile
import warnings
import zipfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
SCENARIO = json.dumps({"format": "thespis-scenario", "version": 5, "name": "seed", "characters": []}).encode()


def manifest(entries, version=1, scenario="play.thespis"):
    return json.dumps({"format": "thespis-package", "version": version, "writer": "make_package_seeds.py",
                       "scenario": scenario,
                       "entries": [{"name": n, "size": len(d), "sha256": hashlib.sha256(d).hexdigest()}
                                   for n, d, *_ in entries]}, indent=2).encode()


def package(path, entries, listed=None):
    listed = entries if listed is None else listed
    with warnings.catch_warnings(), zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as archive:
        warnings.simplefilter("ignore")
        archive.writestr("manifest.json", manifest(listed))
        for name, data, *link in entries:
            info = zipfile.ZipInfo(name)
            info.compress_type = zipfile.ZIP_DEFLATED
            if link:
                info.create_system, info.external_attr = 3, 0o120777 << 16
            archive.writestr(info, data)


def main():
    manifests = HERE / "corpus" / "manifest"
    packages = HERE / "corpus" / "package"
    manifests.mkdir(parents=True, exist_ok=True)
    packages.mkdir(parents=True, exist_ok=True)
    play, clip = ("play.thespis", SCENARIO), ("motion/a.bvh", b"HIERARCHY\nROOT Hips\n{\n}\n")
    (manifests / "valid.json").write_bytes(manifest([play, clip]))
    (manifests / "newer.json").write_bytes(manifest([play], version=3))
    (manifests / "climbing_name.json").write_bytes(manifest([play, ("../a.bvh", b"x")]))
    bad = json.loads(manifest([play]))
    bad["entries"][0]["sha256"] = "XYZ"
    (manifests / "bad_digest.json").write_bytes(json.dumps(bad).encode())
    package(packages / "small.thespkg", [play, clip])
    package(packages / "climbing.thespkg", [play, ("../../a.bvh", b"x")])
    package(packages / "link.thespkg", [play, ("motion/a.bvh", b"/etc/passwd", True)])
    package(packages / "twice.thespkg", [play, clip, clip], listed=[play, clip])
    with tempfile.TemporaryDirectory() as folder:
        scenario = json.loads(SCENARIO)
        scenario["characters"] = [{"name": "A", "skeleton": "hanim-loa1", "clips": [{"name": "a", "file": "a.bvh"}]}]
        (Path(folder) / "seed.thespis").write_text(json.dumps(scenario))
        (Path(folder) / "a.bvh").write_bytes(clip[1])
        subprocess.run([os.environ["THESPIS_CLI"], "export", Path(folder) / "seed.thespis",
                        "--out", packages / "exported.thespkg", "--quiet"], check=True)


if __name__ == "__main__":
    main()
