#!/usr/bin/env python3
"""Rewrites tests/test_costs.txt from the last runs' ctest cost data (why the file exists: its
header). Run after `make test` and scripts/sanitize.sh on an otherwise idle machine:

    scripts/refresh_test_costs.py [--release build] [--sanitizer build-asan] [--min 4]

A test is listed when either run took at least --min seconds; a test the sanitizer run left
out (or that has no record there) gets 0 in that column. The header comment is kept."""
import argparse
import pathlib
import sys


def costs(build_dir):
    path = pathlib.Path(build_dir) / 'Testing' / 'Temporary' / 'CTestCostData.txt'
    if not path.exists():
        sys.exit(f'refresh_test_costs: no {path}: run the tests there first')
    result = {}
    for line in path.read_text().splitlines():
        if line.startswith('---'):  # ctest lists the failed tests after this line
            break
        fields = line.split()
        # "name runs seconds"; a parameterised test's name has no spaces, its GetParam() comment is not kept
        if len(fields) == 3:
            result[fields[0]] = float(fields[2])
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--release', default='build')
    parser.add_argument('--sanitizer', default='build-asan')
    parser.add_argument('--min', type=float, default=4.0)
    args = parser.parse_args()
    root = pathlib.Path(__file__).resolve().parent.parent
    target = root / 'tests' / 'test_costs.txt'
    header = [l for l in target.read_text().splitlines() if l.startswith('#')]
    release, sanitizer = costs(root / args.release), costs(root / args.sanitizer)
    names = [n for n in set(release) | set(sanitizer) if max(release.get(n, 0), sanitizer.get(n, 0)) >= args.min]
    names.sort(key=lambda n: (-max(release.get(n, 0), sanitizer.get(n, 0)), n))
    rows = [f'{n} {round(release.get(n, 0))} {round(sanitizer.get(n, 0))}' for n in names]
    target.write_text('\n'.join(header + rows) + '\n')
    print(f'refresh_test_costs: {len(rows)} tests written to {target.relative_to(root)}')


if __name__ == '__main__':
    main()
