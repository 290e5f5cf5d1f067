#!/usr/bin/env python3
"""TestReadmeDefaults: the parameter tables of README.md state the C++ defaults.

Every row of a "### Parameters" table under a "## vtkXxx" heading names one or more
properties (`Name`, `Name2`) and their defaults ("on", "off", a number, or "0 `ENUM`").
For each filter the test creates the wrapped class and compares every documented default
with its Get<Name>(); it also fails when a table documents no parameter at all, so a
renamed heading or table cannot make the test pass vacuously, and when a row gives several
defaults but not one per name. With the command-line program as second argument it also
compares the "(default X" of every option of `foldingmeshes --help` that sets a filter
parameter with that parameter's C++ default (the program sets only the options given).

    PYTHONPATH=<build>/lib/python3/dist-packages TestReadmeDefaults.py README.md [foldingmeshes]
"""

import re
import subprocess
import sys

import foldingmeshes


def parse_tables(text):
    """{class name: [(property, default text)]} from the README's parameter tables."""
    tables, current = {}, None
    for line in text.splitlines():
        heading = re.match(r"^## (vtk\w+)\s*$", line)
        if heading:
            current = heading.group(1)
            continue
        if line.startswith("## "):
            current = None
        if current is None or not line.startswith("| `"):
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        names = re.findall(r"`(\w+)`", cells[0])
        defaults = [d.strip() for d in cells[1].split(",")]
        if len(defaults) != len(names):
            if len(defaults) != 1:
                raise ValueError("README row %s: %d names, %d defaults"
                                 % (cells[0], len(names), len(defaults)))
            defaults = defaults * len(names)
        tables.setdefault(current, []).extend(zip(names, defaults))
    return tables


def parse_default(text):
    text = text.strip()
    if text.startswith("none"):  # an object property whose default is no object
        return None
    if text == "on":
        return True
    if text == "off":
        return False
    vector = re.match(r"^\(([^)]*)\)$", text)
    if vector:
        return tuple(float(x) for x in vector.group(1).split())
    number = re.match(r"^(-?[0-9.eE+-]+)", text)
    if not number:
        raise ValueError("cannot read default '%s'" % text)
    return float(number.group(1))


# Options of `foldingmeshes --help` whose "(default X" states a filter parameter's default:
# (command section, option) -> (class, property).
CLI_OPTIONS = {
    ("detect", "--tolerance"): ("vtkSymmetryPlaneDetector", "Tolerance"),
    ("detect", "--candidates"): ("vtkSymmetryPlaneDetector", "NumberOfCandidates"),
    ("detect", "--seed"): ("vtkSymmetryPlaneDetector", "RandomSeed"),
    ("detect", "--sampled-search-above"): ("vtkSymmetryPlaneDetector", "SampledSearchAboveFaces"),
    ("fold", "--tolerance"): ("vtkFoldingTreeBuilder", "Tolerance"),
    ("fold", "--min-area-fraction"): ("vtkFoldingTreeBuilder", "MinimumAreaFraction"),
    ("fold", "--max-folds"): ("vtkFoldingTreeBuilder", "MaximumFolds"),
    ("fold", "--min-faces"): ("vtkFoldingTreeBuilder", "MinimumFaces"),
    ("fold", "--seed"): ("vtkFoldingTreeBuilder", "RandomSeed"),
    ("fold", "--sampled-search-above"): ("vtkFoldingTreeBuilder", "SampledSearchAboveFaces"),
    ("fold", "--max-rotation-order"): ("vtkFoldingTreeBuilder", "MaximumRotationOrder"),
}


def check_command_line(program):
    """Failures among the CLI_OPTIONS defaults stated by `program --help`."""
    usage = subprocess.run([program, "--help"], capture_output=True, text=True,
                           check=True).stdout
    section, texts, current = None, {}, None
    for line in usage.splitlines():
        heading = re.match(r"^(\w+): ", line)
        option = re.match(r"^  (--[\w-]+)", line)
        if heading:
            section, current = heading.group(1), None
        elif option and section:
            current = (section, option.group(1))
            texts[current] = line
        elif current and line.startswith(" " * 20):  # an option's continuation line
            texts[current] += " " + line.strip()
        else:
            current = None
    stated = {}
    for key, text in texts.items():
        default = re.search(r"\(default ([-0-9.eE+]+)", text)
        if default:
            stated[key] = float(default.group(1))
    failures = 0
    for (section, option), (class_name, name) in CLI_OPTIONS.items():
        actual = getattr(getattr(foldingmeshes, class_name)(), "Get" + name)()
        ok = (section, option) in stated and \
            abs(stated[(section, option)] - actual) <= 1e-12 * max(1.0, abs(actual))
        print("%s %s %s: --help %s, C++ %s.%s %s" % (
            "ok    " if ok else "FAILED", section, option, stated.get((section, option)),
            class_name, name, actual))
        failures += 0 if ok else 1
    return failures


def main():
    text = open(sys.argv[1], encoding="utf-8").read()
    tables = parse_tables(text)
    failures = 0
    for class_name in ("vtkSymmetryPlaneDetector", "vtkFoldingTreeBuilder",
                       "vtkFoldingTreeUnfolder"):
        rows = tables.get(class_name, [])
        if not rows:
            print("FAILED: README documents no parameter of %s" % class_name)
            failures += 1
            continue
        instance = getattr(foldingmeshes, class_name)()
        # Every property the class adds to vtkPolyDataAlgorithm must be documented.
        from vtkmodules.vtkCommonExecutionModel import vtkPolyDataAlgorithm
        inherited = set(dir(vtkPolyDataAlgorithm))
        members = set(dir(instance))
        settable = sorted(m[3:] for m in members
                          if m.startswith("Set") and m not in inherited and "Get" + m[3:] in members
                          and not m.endswith("Connection") and not m.endswith("Data")
                          # The MPI controller is documented under "Parallel runs".
                          and m != "SetController")
        documented = {name for name, _ in rows}
        for name in settable:
            if name not in documented:
                print("FAILED: %s.%s is not documented in the README" % (class_name, name))
                failures += 1
        for name, default in rows:
            getter = getattr(instance, "Get" + name, None)
            if getter is None:
                print("FAILED: %s has no property %s (README)" % (class_name, name))
                failures += 1
                continue
            actual, documented = getter(), parse_default(default)
            if documented is None or actual is None:
                ok = documented is None and actual is None
            elif isinstance(documented, tuple) or isinstance(actual, tuple):
                ok = (isinstance(documented, tuple) and isinstance(actual, tuple) and
                      len(actual) == len(documented) and
                      all(abs(a - d) <= 1e-12 for a, d in zip(actual, documented)))
            else:
                ok = abs(float(actual) - float(documented)) <= 1e-12 * max(1.0, abs(documented))
            print("%s %s.%s: README %s, C++ %s" % ("ok    " if ok else "FAILED", class_name,
                                                   name, default, actual))
            failures += 0 if ok else 1
    if len(sys.argv) > 2:
        failures += check_command_line(sys.argv[2])
    print("%d failure(s)" % failures if failures else "all README defaults equal the C++ ones")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
