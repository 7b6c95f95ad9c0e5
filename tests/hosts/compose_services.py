#!/usr/bin/env python3
"""Reads deploy/containers/compose.yaml as compose would (merge keys, ${VAR:-default} and
${VAR:?message} from the environment) and writes, per service, what its container runs:
OUT/<service>.argv (the command, NUL-separated) and OUT/<service>.env (NAME=value lines: the
image's ENV from the Containerfile, then the service's environment). Prints the service names."""
import argparse
import os
import re
import sys

import yaml

VAR = re.compile(r"\$\{([A-Za-z_][A-Za-z0-9_]*)(?:(:-|:\?)([^}]*))?\}")


def interpolate(text: str, where: str) -> str:
    def one(m):
        name, op, arg = m.group(1), m.group(2), m.group(3)
        value = os.environ.get(name, "")
        if value:
            return value
        if op == ":-":
            return arg
        if op == ":?":
            sys.exit(f"{where}: {name}: {arg}")
        return ""
    return VAR.sub(one, text)


def image_env(containerfile: str) -> dict:
    """ENV lines of the Containerfile (NAME=value pairs, continued lines joined)."""
    text = open(containerfile).read().replace("\\\n", " ")
    env = {}
    for line in text.splitlines():
        if line.startswith("ENV "):
            for pair in line[4:].split():
                name, _, value = pair.partition("=")
                env[name] = value
    return env


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--compose", required=True)
    ap.add_argument("--containerfile", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    doc = yaml.safe_load(open(a.compose))
    base_env = image_env(a.containerfile)
    os.makedirs(a.out, exist_ok=True)
    for name, svc in doc["services"].items():
        where = f"{a.compose}: services.{name}"
        argv = [interpolate(str(w), where) for w in svc["command"]]
        env = dict(base_env)
        for k, v in (svc.get("environment") or {}).items():
            env[k] = interpolate(str(v), where)
        # PATH as the image sets it: its $PATH is Debian's default.
        env["PATH"] = env.get("PATH", "$PATH").replace(
            "$PATH", "/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin")
        with open(os.path.join(a.out, name + ".argv"), "wb") as f:
            f.write(b"\0".join(w.encode() for w in argv) + b"\0")
        with open(os.path.join(a.out, name + ".env"), "w") as f:
            f.writelines(f"{k}={v}\n" for k, v in env.items())
        print(name)
    return 0


if __name__ == "__main__":
    sys.exit(main())
