"""pip install --no-index --no-build-isolation .  (docs/python.md)

Builds the Python module with the project's CMake into build-pip/ (apart from setuptools' own
build/ and from the CMake build in build/) and installs the package `membra` with its native
part. Debian 12 has no scikit-build-core, hence this small driver.
"""

import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    """Builds the target membra_python with CMake and copies the package into build_lib."""

    def build_extension(self, ext):
        build = ROOT / "build-pip"
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build), "-G", "Ninja",
                        "-DCMAKE_BUILD_TYPE=Release", "-DMEMBRA_BUILD_TESTS=OFF",
                        "-DMEMBRA_BUILD_BENCHMARKS=OFF", f"-DPython3_EXECUTABLE={sys.executable}"],
                       check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "membra_python"], check=True)
        target = Path(self.build_lib) / "membra"
        shutil.rmtree(target, ignore_errors=True)
        shutil.copytree(build / "python" / "membra", target)
        native = next(target.glob("_membra*.so"))
        Path(self.get_ext_fullpath(ext.name)).parent.mkdir(parents=True, exist_ok=True)
        if Path(self.get_ext_fullpath(ext.name)) != native:
            shutil.copy2(native, self.get_ext_fullpath(ext.name))


setup(
    name="membra",
    version=re.search(r"project\(membra VERSION (\S+)", (ROOT / "CMakeLists.txt").read_text())[1],
    description="Form-finding for pre-stretched, resin-impregnated membranes",
    packages=["membra"],
    package_dir={"membra": "python/membra"},
    ext_modules=[Extension("membra._membra", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": "build-pip/setuptools"}},  # not CMake's build/
    python_requires=">=3.9",
)
