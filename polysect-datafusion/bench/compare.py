#!/usr/bin/env python3
"""The other side of docs/datafusion.md's benchmark: SedonaDB's and geopandas' spatial
joins on the same GeoParquet tables as `polysect-datafusion join`, and the count of
pairs an engine gets wrong against polysect's exact answer.

Not used by any test. Needs `pip install sedonadb geopandas shapely pyarrow
geoarrow-pyarrow` (SedonaDB registers its Arrow extension types with the last).

    compare.py join sedonadb  A.parquet B.parquet --out pairs.csv
    compare.py join geopandas A.parquet B.parquet --out pairs.csv
    compare.py diff exact.csv pairs.csv

`join` prints one line of `key=value` fields: the engine, the seconds spent reading
the tables and joining them (and their sum), the pair count and the process's peak
resident memory (`getrusage`, in MiB; run one engine per process so that the peak is
that engine's). `--out` writes the pairs as CSV `left_id,right_id` sorted, the format
`polysect-datafusion join` prints. `diff` prints how many pairs of the second file are
not in the first (false positives) and how many of the first are missing from the
second (false negatives), with a few of each.
"""

import argparse
import csv
import resource
import sys
import time


def peak_mib():
    # Linux reports ru_maxrss in KiB.
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def join_sedonadb(left, right, geometry, threads):
    import sedonadb

    started = time.perf_counter()
    sd = sedonadb.connect()
    if threads:
        sd.sql(f"SET datafusion.execution.target_partitions = {threads}").execute()
    sd.read_parquet(left).to_view("a")
    sd.read_parquet(right).to_view("b")
    read = time.perf_counter() - started
    table = sd.sql(
        f"SELECT a.id AS left_id, b.id AS right_id FROM a JOIN b "
        f"ON ST_Intersects(a.{geometry}, b.{geometry})"
    ).to_arrow_table()
    total = time.perf_counter() - started
    left_ids = table.column("left_id").to_pylist()
    right_ids = table.column("right_id").to_pylist()
    return read, total - read, list(zip(left_ids, right_ids))


def join_geopandas(left, right, geometry):
    import geopandas

    started = time.perf_counter()
    a = geopandas.read_parquet(left).set_geometry(geometry)
    b = geopandas.read_parquet(right).set_geometry(geometry)
    read = time.perf_counter() - started
    # sjoin builds an STRtree over the right frame and refines with GEOS.
    joined = geopandas.sjoin(a, b, how="inner", predicate="intersects", lsuffix="l", rsuffix="r")
    total = time.perf_counter() - started
    return read, total - read, list(zip(joined["id_l"].tolist(), joined["id_r"].tolist()))


def write_pairs(path, pairs):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["left_id", "right_id"])
        w.writerows(sorted(pairs))


def read_pairs(path):
    with open(path, newline="") as f:
        rows = csv.reader(f)
        header = next(rows, None)
        if header != ["left_id", "right_id"]:
            sys.exit(f"{path}: expected the header left_id,right_id, found {header}")
        out = set()
        for line, row in enumerate(rows, start=2):
            if len(row) != 2:
                sys.exit(f"{path}:{line}: expected two ids, found {row}")
            out.add((int(row[0]), int(row[1])))
        return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    j = sub.add_parser("join", help="run one engine's intersects join")
    j.add_argument("engine", choices=["sedonadb", "geopandas"])
    j.add_argument("left")
    j.add_argument("right")
    j.add_argument("--geometry", default="geometry")
    j.add_argument("--threads", type=int, default=0, help="SedonaDB's target partitions (0: its default)")
    j.add_argument("--out", help="write the pairs here (CSV left_id,right_id)")
    d = sub.add_parser("diff", help="wrong pairs of an engine against the exact answer")
    d.add_argument("exact")
    d.add_argument("other")
    d.add_argument("--show", type=int, default=5, help="how many wrong pairs of each kind to print")
    args = parser.parse_args()

    if args.command == "join":
        if args.engine == "sedonadb":
            read, join, pairs = join_sedonadb(args.left, args.right, args.geometry, args.threads)
        else:
            read, join, pairs = join_geopandas(args.left, args.right, args.geometry)
        distinct = len(set(pairs))
        print(
            f"engine={args.engine} read_s={read:.3f} join_s={join:.3f} total_s={read + join:.3f} "
            f"pairs={len(pairs)} distinct={distinct} peak_mib={peak_mib():.0f}"
        )
        if args.out:
            write_pairs(args.out, pairs)
    else:
        exact, other = read_pairs(args.exact), read_pairs(args.other)
        extra = sorted(other - exact)
        missing = sorted(exact - other)
        print(
            f"exact={len(exact)} other={len(other)} false_positives={len(extra)} "
            f"false_negatives={len(missing)} wrong={len(extra) + len(missing)}"
        )
        for name, pairs in (("false positive", extra), ("false negative", missing)):
            for p in pairs[: args.show]:
                print(f"  {name}: {p[0]},{p[1]}")


if __name__ == "__main__":
    main()
