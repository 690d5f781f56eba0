"""The command line every plot of an output folder shares: `--out FOLDER`,
the folder a rollcheck command wrote, and the JSON summary it holds there."""
import argparse
import json
import os


def read_summary(doc, file_name, help_text):
    """Parses --out (help `help_text`, description the first line of `doc`) and
    returns the folder and its `file_name` parsed as JSON."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--out", required=True, help=help_text)
    args = parser.parse_args()
    with open(os.path.join(args.out, file_name)) as f:
        return args.out, json.load(f)
