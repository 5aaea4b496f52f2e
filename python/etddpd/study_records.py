"""A study's records in one file: the small LAMMPS output files (fix ave/time and ave/chunk
blocks, run tables) that its tables and figures are generated from, kept as one JSON object
{relative path: text} instead of one tracked file each. The logs are not records: the drivers
regenerate them.

  study_records.py pack DIR RECORDS [GLOB ...]   merge DIR's files matching the globs (default
                                                 every file but log.*) into RECORDS
  study_records.py unpack RECORDS DIR            write RECORDS' files into DIR where DIR lacks them
                                                 (a fresh run's output is not overwritten)
"""
import argparse
import fnmatch
import json
import os


def read(path):
    """{relative path: text} of a records file; empty if there is none."""
    if not os.path.exists(path):
        return {}
    with open(path) as handle:
        return json.load(handle)


def pack(directory, path, globs=None):
    """Merge the files under `directory` matching `globs` (relative paths; default: every file
    whose name does not start with 'log.') into the records at `path`. Returns the records."""
    records = read(path)
    skip = os.path.abspath(path)
    for root, _, names in os.walk(directory):
        for name in sorted(names):
            full = os.path.join(root, name)
            relative = os.path.relpath(full, directory)
            if os.path.abspath(full) == skip:
                continue
            if globs:
                if not any(fnmatch.fnmatch(relative, g) for g in globs):
                    continue
            elif name.startswith("log.") or name.endswith(".json"):
                continue
            with open(full) as handle:
                records[relative] = handle.read()
    with open(path, "w") as handle:
        json.dump(dict(sorted(records.items())), handle, indent=0)
        handle.write("\n")
    return records


def unpack(path, directory):
    """Write the records' files into `directory` where it lacks them; returns the paths written."""
    written = []
    for relative, text in read(path).items():
        full = os.path.join(directory, relative)
        if os.path.exists(full):
            continue
        os.makedirs(os.path.dirname(full) or ".", exist_ok=True)
        with open(full, "w") as handle:
            handle.write(text)
        written.append(full)
    return written


def main(argv=None):
    parser = argparse.ArgumentParser(description="A study's records in one JSON file.")
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("pack")
    p.add_argument("directory")
    p.add_argument("records")
    p.add_argument("globs", nargs="*")
    u = sub.add_parser("unpack")
    u.add_argument("records")
    u.add_argument("directory")
    args = parser.parse_args(argv)
    if args.command == "pack":
        print(f"{len(pack(args.directory, args.records, args.globs))} files in {args.records}")
    else:
        print(f"{len(unpack(args.records, args.directory))} files written into {args.directory}")
    return 0
