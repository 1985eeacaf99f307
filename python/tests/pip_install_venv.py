#!/usr/bin/env python3
"""`pip install .` as a new user would, offline: a fresh venv (with the system's site
packages: Debian's numpy and setuptools), `pip install --no-build-isolation --no-index`,
then a fresh interpreter of that venv imports brdftab from its site-packages (not from the
source or build tree) and calls it, exact and table methods (the tables installed with it).

    pip_install_venv.py SOURCE_DIR WORK_DIR
Exit 0 on success. Environment: BRDFTAB_CMAKE_BUILD_DIR (reused between runs), see setup.py.
"""
import os
import shutil
import subprocess
import sys

source, work = sys.argv[1], sys.argv[2]
venv = os.path.join(work, "venv")
shutil.rmtree(venv, ignore_errors=True)
os.makedirs(work, exist_ok=True)
subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", venv], check=True)
py = os.path.join(venv, "bin", "python")
env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "BRDFTAB_TABLES")}
env["PIP_NO_INDEX"] = "1"  # offline: nothing may be downloaded
env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
env["BRDFTAB_SETUPTOOLS_BUILD"] = os.path.join(work, "setuptools-build")
shutil.rmtree(env["BRDFTAB_SETUPTOOLS_BUILD"], ignore_errors=True)
subprocess.run([py, "-m", "pip", "install", "--no-build-isolation", "--no-index", "-q", source], check=True, env=env)

check = r'''
import os, sys
import numpy as np
import brdftab
site = os.path.realpath(brdftab.__file__)
assert site.startswith(os.path.realpath(sys.prefix)), site   # the venv's copy
print("brdftab", brdftab.__version__, "from", site)
h = brdftab.h_iso(1.0, 1.0)                                   # Chandrasekhar: 2.90781
assert abs(h - 2.90781) < 1e-5, h
e = brdftab.lookup.microfacet_albedo(np.array([0.2, 0.9], np.float32), 0.3)  # bundled tables
assert e.dtype == np.float32 and np.all((e > 0) & (e < 1)), e
r = brdftab.microfacet_albedo_ggx(0.5, 0.3, method="table")
assert abs(r.E_corr - brdftab.microfacet_albedo_ggx(0.5, 0.3).E_corr) < 1e-5
print("ok")
'''
os.chdir(work)  # not the source tree: nothing found by accident in the current folder
subprocess.run([py, "-c", check], check=True, env=env)
