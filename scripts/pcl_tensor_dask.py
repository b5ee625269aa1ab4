#!/usr/bin/env python3
"""pcl_tensor_model's work as jobs on a Dask cluster: one per view, then per chunk of pairs.

    python3 scripts/pcl_tensor_dask.py VIEW.ply... -o model.ply --cache DIR [--scheduler ADDRESS]
        [--workers N] [--rank K] [--bin BUILD/apps] [tool options: --viewpoint x,y,z --faces N --loop ...]

Stages (the same view list, in the same order, everywhere):
  1. meshes   one `pcl_tensor_prepare VIEW --cache DIR` per view
  2. tensors  one `pcl_tensor_prepare VIEWS... --cache DIR --tensors --only VIEW` per view (D needs
              every view's extents, which stage 1 put in the cache)
  3. ranking  one `pcl_tensor_pairs VIEWS... --rank K`: each view's K best partners
  4. pairs    those pairs in chunks (about 2 per worker thread), one `pcl_tensor_pairs --pairs CHUNK` each
  5. model    `pcl_tensor_model VIEWS... --cache DIR --pairs-results R1 --pairs-results R2 ... -o model.ply`,
              here, on this machine (the graph, the global step and integration)

Without --scheduler it starts a LocalCluster of --workers processes (default 2) of one thread each. With
--scheduler, every worker must see the same files at the same absolute paths: the views, the cache
folder (a shared file system: NFS, ...) and the tools (--bin, or on PATH). Each job runs one tool on one
thread; give a machine's workers one thread per core (dask-worker --nthreads N).

Options the driver does not know are passed to every tool (each takes those it knows), except --dims,
which pcl_tensor_prepare takes only with --tensors. Exit codes: pcl_tensor_model's (0 every view
registered, 3 some not), 2 bad usage, else the exit code of the first job that failed, whose command
and stderr are printed.
"""
import argparse
import hashlib
import os
import shutil
import subprocess
import sys
import time

TOOLS = ("pcl_tensor_prepare", "pcl_tensor_pairs", "pcl_tensor_model")
# Options the driver sets itself: given among the tool options, they would contradict it.
RESERVED = ("--cache", "--pairs", "--pairs-results", "--rank", "--only", "--tensors", "--json", "-o")
# Pair chunks per worker thread: a slow chunk then leaves the others busy (the pairs differ in cost).
CHUNKS_PER_WORKER = 2
# How long a cluster may take to get its first worker: jobs would wait for one forever.
WORKER_WAIT_SECONDS = 120


def run_tool(command):
    """Run one tool; what it did, for the driver to check. Runs on a worker."""
    start = time.monotonic()
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    return {"command": command, "code": done.returncode, "stdout": done.stdout, "stderr": done.stderr,
            "seconds": time.monotonic() - start, "host": os.uname().nodename}


class JobFailed(Exception):
    def __init__(self, stage, result):
        super().__init__(stage)
        self.stage, self.result = stage, result


def parse_args(argv):
    parser = argparse.ArgumentParser(
        description="Build a model from range images with pcl_tensor's tools as jobs on Dask distributed.",
        epilog="Other options are passed to the tools (e.g. --viewpoint 0,0,0 --faces 1000 --loop).",
        allow_abbrev=False)
    parser.add_argument("-o", "--output", required=True, help="the model (PLY); its poses go beside it (.conf)")
    parser.add_argument("--cache", required=True,
                        help="the cache folder (pcl_tensor_prepare's); on a file system every worker shares")
    parser.add_argument("--scheduler", help="a Dask scheduler's address (tcp://host:8786); default: a LocalCluster")
    parser.add_argument("--workers", type=int, default=2, help="LocalCluster workers, one thread each (default 2)")
    parser.add_argument("--rank", type=int, default=3, help="candidate pairs: each view's K best partners (default 3)")
    parser.add_argument("--bin", help="folder of the tools (default: build/apps beside this script, else PATH)")
    args, rest = parser.parse_known_args(argv)
    args.views = [os.path.abspath(a) for a in rest if a.lower().endswith((".ply", ".pcd"))]
    args.tool_options = [a for a in rest if not a.lower().endswith((".ply", ".pcd"))]
    for option in args.tool_options:
        if option in RESERVED:
            parser.error(f"{option} is set by the driver; see --help")
    if len(args.views) < 2:
        parser.error("expected at least two VIEW files (.ply or .pcd)")
    if args.workers < 1 or args.rank < 1:
        parser.error("--workers and --rank take 1 or more")
    args.output = os.path.abspath(args.output)
    args.cache = os.path.abspath(args.cache)
    args.tools = find_tools(parser, args.bin)
    return args


def find_tools(parser, folder):
    """Absolute paths of the tools, as every worker must find them."""
    if folder is None:
        beside = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build", "apps")
        folder = beside if os.path.isfile(os.path.join(beside, TOOLS[0])) else None
    tools = {}
    for name in TOOLS:
        path = os.path.join(folder, name) if folder else shutil.which(name)
        if not path or not os.access(path, os.X_OK):
            parser.error(f"{name} not found (--bin {folder})" if folder else f"{name} is not on PATH: give --bin")
        tools[name] = os.path.abspath(path)
    return tools


def without_option(options, name, values=1):
    """`options` less `name` and the values that follow it."""
    kept, skip = [], 0
    for option in options:
        if skip:
            skip -= 1
        elif option == name:
            skip = values
        else:
            kept.append(option)
    return kept


def start_client(args):
    from dask.distributed import Client, LocalCluster
    if args.scheduler:
        client = Client(args.scheduler)
        try:
            client.wait_for_workers(1, timeout=WORKER_WAIT_SECONDS)
        except TimeoutError:
            client.close()
            raise SystemExit(f"pcl_tensor_dask: error: no worker joined {args.scheduler} in {WORKER_WAIT_SECONDS} s")
        return client, None
    cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True, dashboard_address=None)
    return Client(cluster), cluster


def run_stage(client, name, commands):
    """Run `commands` as jobs, all at once; stop at the first that fails."""
    from dask.distributed import as_completed
    start = time.monotonic()
    futures = client.map(run_tool, commands, pure=False)
    results = []
    for future in as_completed(futures):
        result = future.result()
        if result["code"] != 0:
            client.cancel(futures)
            raise JobFailed(name, result)
        results.append(result)
    busy = sum(r["seconds"] for r in results)
    print(f"{name}: {len(commands)} job(s) in {time.monotonic() - start:.1f} s (jobs' sum {busy:.1f} s)", flush=True)
    return results


def work_folder(args):
    """Where the pairs and results go: in the shared cache, one folder per set of views and options."""
    key = hashlib.sha1("\n".join(args.views + args.tool_options + [str(args.rank)]).encode()).hexdigest()[:12]
    return os.path.join(args.cache, "pairs-" + key)


def read_pairs(path):
    with open(path) as f:
        return [line for line in f if line.strip() and not line.startswith("#")]


def write_chunks(pairs, chunks, folder):
    """`pairs` dealt round-robin into `chunks` files (a high-ranked and a low-ranked pair each)."""
    paths = []
    for c in range(chunks):
        path = os.path.join(folder, f"chunk_{c:03d}.txt")
        with open(path, "w") as f:
            f.writelines(pairs[c::chunks])
        paths.append(path)
    return paths


def worker_threads(client):
    return max(1, sum(w["nthreads"] for w in client.scheduler_info()["workers"].values()))


def run(args, client):
    views, options, cache = args.views, args.tool_options, args.cache
    prepare, pairs_tool = args.tools["pcl_tensor_prepare"], args.tools["pcl_tensor_pairs"]
    one_thread = ["-j", "1"]  # before the user's options: the first -j counts
    folder = work_folder(args)
    mesh_options = without_option(options, "--dims")
    run_stage(client, "1 meshes", [[prepare, v, "--cache", cache] + one_thread + mesh_options for v in views])
    run_stage(client, "2 tensors",
              [[prepare] + views + ["--cache", cache, "--tensors", "--only", v] + one_thread + options for v in views])
    os.makedirs(folder, exist_ok=True)
    candidates = os.path.join(folder, "candidates.txt")
    run_stage(client, "3 ranking", [[pairs_tool] + views + ["--cache", cache, "--rank", str(args.rank), "-o", candidates]
                                    + options])
    pairs = read_pairs(candidates)
    chunks = write_chunks(pairs, max(1, min(len(pairs), CHUNKS_PER_WORKER * worker_threads(client))), folder)
    results = [c.replace("chunk_", "results_").replace(".txt", ".jsonl") for c in chunks]
    run_stage(client, "4 pairs", [[pairs_tool] + views + ["--cache", cache, "--pairs", c, "-o", r] + one_thread + options
                                  for c, r in zip(chunks, results)])
    print(f"  {len(pairs)} candidate pairs in {len(chunks)} chunk(s): {folder}", flush=True)
    model = [args.tools["pcl_tensor_model"]] + views + ["--cache", cache, "-o", args.output] + options
    for r in results:
        model += ["--pairs-results", r]
    start = time.monotonic()
    done = subprocess.run(model)
    print(f"5 model: here in {time.monotonic() - start:.1f} s", flush=True)
    if done.returncode not in (0, 3):
        raise JobFailed("5 model", {"command": model, "code": done.returncode, "stderr": "(above)",
                                    "host": os.uname().nodename})
    return done.returncode


def main(argv):
    args = parse_args(argv)
    try:
        import dask.distributed  # noqa: F401
    except ImportError:
        print("pcl_tensor_dask: error: needs dask.distributed (Debian: apt-get install python3-distributed, "
              "for /usr/bin/python3)", file=sys.stderr)
        return 2
    client, cluster = start_client(args)
    try:
        return run(args, client)
    except JobFailed as failure:
        r = failure.result
        print(f"pcl_tensor_dask: error: stage {failure.stage}: exit code {r['code']} on {r['host']} from\n  "
              + " ".join(r["command"]) + "\n" + r["stderr"].rstrip(), file=sys.stderr)
        return r["code"] if 0 < r["code"] < 256 else 1
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
