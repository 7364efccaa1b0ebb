"""`airshape study STUDY.toml -o results.csv`: the command line of a study (docs/studies.md).
Exit status: 0 every sample done, 1 some failed, 2 the study or its file cannot be used,
130 interrupted by Ctrl-C (what is done is kept; the same command resumes it)."""
from __future__ import annotations

import argparse
import sys
from typing import List, Optional

from ..errors import Error
from .definition import Study, StudyError

USAGE = "airshape study STUDY.toml -o RESULTS.csv|.jsonl [--workers N] [--scheduler tcp://HOST:PORT] [--restart] [--quiet]"


def main(arguments: Optional[List[str]] = None) -> int:
    parser = argparse.ArgumentParser(prog="airshape study", usage=USAGE, description=(
        "Runs a parameter study of a CPACS file: every sample of its design set into the document, "
        "the outputs measured on the rebuilt geometry, a row per sample in the results (docs/studies.md)."))
    parser.add_argument("study", help="the study, a TOML file")
    parser.add_argument("-o", "--output", required=True, help="the results table, .csv or .jsonl; "
                        "samples it holds already are not run again")
    parser.add_argument("--workers", type=int, help="local worker processes (default: one per core)")
    parser.add_argument("--scheduler", help="a Dask scheduler's address (tcp://HOST:PORT) to run on its cluster")
    parser.add_argument("--restart", action="store_true", help="discard what the results file holds")
    parser.add_argument("--quiet", "-q", action="store_true", help="no progress on stderr")
    options = parser.parse_args(arguments)
    try:
        study = Study.from_toml(options.study)
        outcome = study.run(options.output, workers=options.workers, scheduler=options.scheduler,
                            progress=not options.quiet, restart=options.restart)
    except (StudyError, ValueError, OSError) as error:
        print(f"airshape study: {error}", file=sys.stderr)
        return 2
    except Error as error:
        where = f" ({error.cpacs_path})" if error.cpacs_path else ""
        message = str(error).splitlines()[0]
        file = error.file or options.study
        print(f"airshape study: {message if message.startswith(file) else file + ': ' + message}{where}",
              file=sys.stderr)
        return 2
    except KeyboardInterrupt:  # before the samples began: nothing done, nothing to keep
        return 130
    except Exception as error:  # noqa: BLE001 - one line, never a traceback
        print(f"airshape study: {options.study}: {type(error).__name__}: {error}".splitlines()[0], file=sys.stderr)
        return 2
    if outcome.interrupted:
        return 130
    return 1 if outcome.failed else 0


if __name__ == "__main__":
    sys.exit(main())
