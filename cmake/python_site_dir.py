"""Prints where, relative to an install prefix, this interpreter finds modules.

Usage: python3 python_site_dir.py PREFIX SITEARCH
SITEARCH is the interpreter's site directory for compiled modules (CMake's
Python3_SITEARCH, e.g. Debian's /usr/lib/python3/dist-packages). If it or
another of the interpreter's site directories lies under PREFIX (Debian:
/usr -> lib/python3/dist-packages, /usr/local ->
lib/python3.11/dist-packages), that one, so the installed module imports
without PYTHONPATH; otherwise SITEARCH relative to the interpreter's own
prefix, the layout it would have under PREFIX.
"""
import os
import site
import sys

prefix, sitearch = (os.path.realpath(p) for p in sys.argv[1:3])
for d in [sitearch] + site.getsitepackages():
    d = os.path.realpath(d)
    if os.path.commonpath([d, prefix]) == prefix:
        print(os.path.relpath(d, prefix))
        break
else:
    print(os.path.relpath(sitearch, os.path.realpath(sys.prefix)))
