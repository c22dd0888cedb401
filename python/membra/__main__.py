"""`python3 -m membra sweep SWEEP.json --out DIR [--scheduler ADDR]`: what `membra sweep` runs
(docs/sweeps.md). Exit codes as docs/cli.md: 0 every scene ran, 2 a bad sweep file, 4 the
outputs cannot be written, 8 the sweep ran but some scenes failed (their rows say why), 130 / 143
stopped by SIGINT / SIGTERM (finished scenes are kept; running it again resumes)."""

import argparse
import signal
import sys


class _Terminated(Exception):
    """SIGTERM, turned into an exception so that the sweep's cluster is closed on the way out."""


def _on_sigterm(signum, frame):
    raise _Terminated()


def main(argv=None):
    parser = argparse.ArgumentParser(prog="membra sweep",
                                     description="Run a sweep of scenes on a Dask cluster")
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("sweep", help="run a sweep file")
    p.add_argument("file", help="sweep file (JSON, docs/sweeps.md)")
    p.add_argument("--out", "-o", help="output folder (default out/<sweep name>)")
    p.add_argument("--scheduler", help="address of a running Dask scheduler, tcp://HOST:8786 "
                   "(default: a local cluster)")
    p.add_argument("--workers", type=int, default=2,
                   help="worker processes of the local cluster (default 2)")
    p.add_argument("--no-resume", action="store_true",
                   help="run every scene again, even those finished by an earlier run")
    p.add_argument("--quiet", "-q", action="store_true", help="no progress lines")
    args = parser.parse_args(argv)

    from . import OutputError, SceneError
    from .sweep_spec import load_sweep
    from .sweeps import sweep

    signal.signal(signal.SIGTERM, _on_sigterm)
    try:
        spec = load_sweep(args.file)
        out = args.out or f"out/{spec['name']}"
        table = sweep(args.file, out, scheduler=args.scheduler, workers=args.workers,
                      resume=not args.no_resume, quiet=args.quiet)
    except SceneError as e:
        print(f"membra: error: {e}", file=sys.stderr)
        return 2
    except (OutputError, OSError) as e:
        print(f"membra: error: {e}", file=sys.stderr)
        return 4
    except (KeyboardInterrupt, _Terminated) as e:
        name = "SIGTERM" if isinstance(e, _Terminated) else "SIGINT"
        print(f"\nmembra: sweep stopped ({name}); the scenes that finished are kept: run the same "
              "command again to resume", file=sys.stderr)
        return 143 if isinstance(e, _Terminated) else 130
    failed = int((table["error"] != "").sum())
    return 8 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
