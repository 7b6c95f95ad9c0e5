#!/usr/bin/env python3
"""Checks deploy/containers without running a container (issue 11 item 3; docs/hosts.md):
- every program a compose service or a Kubernetes Deployment runs exists (the build's bin/ or
  fast-discovery-server), and every option it is given is one the program has; a federate's
  whole command line is accepted (`--print-ports` builds its component from the options);
- compose.yaml runs deploy/default.yaml's federates with the same arguments (paths mapped to
  /opt/fedsim), the timing federate expects exactly the lockstep services;
- the Kubernetes manifests run the same commands and environment as compose.yaml (the timing
  federate excepted as documented there), and the Services select existing Deployments;
- every participant profile named exists in qos/fedsim_qos.xml; the Containerfile's base is
  the image build-base-image.sh imports.
A negative control runs the same checks on a copy with an unknown option and must fail."""
import argparse
import atexit
import copy
import os
import re
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import yaml

NOT_LOCKSTEP = {"discovery", "ios"}
# Arguments compose adds or changes relative to deploy/default.yaml, and why.
DEFAULT_EXCEPTIONS = {
    "ios": "listens beyond loopback in a container (--bind 0.0.0.0, a fixed port, a token)",
}


class Checker:
    def __init__(self, bin_dir, source):
        self.bin_dir, self.source = bin_dir, source
        self.errors = []
        self.help_cache = {}
        self.profiles = self.profiles_in(os.path.join(source, "qos/fedsim_qos.xml"))
        # /opt/fedsim/containers as the Containerfile makes it.
        self.image_containers = tempfile.mkdtemp(prefix="fedsim-containers-check-")
        atexit.register(shutil.rmtree, self.image_containers, True)
        here = os.path.join(source, "deploy/containers")
        for f in ("fedsim_container_monitor.xml", "make-monitor-qos.sh"):
            shutil.copy(os.path.join(here, f), self.image_containers)
        subprocess.run([os.path.join(here, "make-monitor-qos.sh"), os.path.join(source, "qos/fedsim_qos.xml"),
                        os.path.join(here, "fedsim_container_monitor.xml"),
                        os.path.join(self.image_containers, "fedsim_qos_monitor.xml")], check=True)

    @staticmethod
    def profiles_in(xml_file):
        ns = {"d": "http://www.eprosima.com/XMLSchemas/fastRTPS_Profiles"}
        root = ET.parse(xml_file).getroot()
        return {p.get("profile_name") for p in root.iterfind(".//d:participant", ns)}

    def error(self, where, text):
        self.errors.append(f"{where}: {text}")

    def local_path(self, word):
        """/opt/fedsim/... in the image is this checkout's file (bin/ is the build's)."""
        word = word.replace("/opt/fedsim/bin", self.bin_dir)
        word = word.replace("/opt/fedsim/containers/", self.image_containers + "/")
        return word.replace("/opt/fedsim/", self.source + "/")

    def program(self, name):
        path = os.path.join(self.bin_dir, name)
        if os.access(path, os.X_OK):
            return path
        return shutil.which(name)

    def options_of(self, argv0_path, sub):
        key = (argv0_path, sub)
        if key not in self.help_cache:
            cmd = [argv0_path] + ([sub] if sub else []) + ["--help"]
            r = subprocess.run(cmd, capture_output=True, text=True, timeout=30)
            self.help_cache[key] = set(re.findall(r"(?<![\w-])(--[a-z0-9][a-z0-9-]*)", r.stdout + r.stderr))
            if argv0_path.endswith("fast-discovery-server"):
                self.help_cache[key] |= set(re.findall(r"(?<![\w-])(-[a-zA-Z])\b", r.stdout + r.stderr))
        return self.help_cache[key]

    def check_command(self, where, argv, env):
        prog = self.program(argv[0])
        if not prog:
            self.error(where, f"program '{argv[0]}' is neither in {self.bin_dir} nor on PATH")
            return
        sub = argv[1] if argv[0] == "fedsim" and len(argv) > 1 else None
        known = self.options_of(prog, sub)
        for word in argv[1:]:
            opt = word.split("=")[0]
            if opt.startswith("-") and not re.match(r"^-?\d", opt) and opt not in known:
                self.error(where, f"{argv[0]}{' ' + sub if sub else ''} has no option '{opt}'")
        for word in argv:
            if word.startswith("/opt/fedsim/") and not word.startswith("/opt/fedsim/out"):
                if not os.path.exists(self.local_path(word)):
                    self.error(where, f"the image has no file {word}")
        qos_file = env.get("FEDSIM_QOS_FILE", "")
        if not qos_file.startswith("/opt/fedsim/") or not os.path.exists(self.local_path(qos_file)):
            self.error(where, f"FEDSIM_QOS_FILE '{qos_file}' is not in the image")
            profiles = set()
        else:
            profiles = self.profiles_in(self.local_path(qos_file))
        for profile in [env.get("FEDSIM_PARTICIPANT_PROFILE")] + [
                argv[i + 1] for i, w in enumerate(argv[:-1]) if w == "--participant-profile"]:
            if profile and profile not in profiles:
                self.error(where, f"participant profile '{profile}' is not in {qos_file}")
        # A federate builds its component from the options: values are checked too.
        if argv[0].startswith("fedsim-") and "--print-ports" in known:
            local = [prog] + [self.local_path(w) for w in argv[1:]] + ["--print-ports"]
            r = subprocess.run(local, capture_output=True, text=True, timeout=60,
                               env={**os.environ, "FEDSIM_IOS_TOKEN": "containers-check-token"})
            if r.returncode != 0:
                self.error(where, f"'{' '.join(argv)} --print-ports' failed: {(r.stderr or r.stdout).strip()[-300:]}")


def interpolate_default(word):
    return re.sub(r"\$\{[A-Za-z_]+:-([^}]*)\}", r"\1", word)


def image_env(containerfile_text):
    env = {}
    for line in containerfile_text.replace("\\\n", " ").splitlines():
        if line.startswith("ENV "):
            for pair in line[4:].split():
                k, _, v = pair.partition("=")
                env[k] = v
    return env


def strip(argv, name):
    """A compose command without what every container adds: its --name."""
    out, i = [], 0
    while i < len(argv):
        if argv[i] == "--name" and i + 1 < len(argv) and argv[i + 1] == name:
            i += 2
            continue
        out.append(argv[i])
        i += 1
    return out


def check_all(c, compose, k8s_docs, default, containerfile_text):
    base_env = image_env(containerfile_text)
    if not re.search(r"^FROM localhost/fedsim-base:bookworm$", containerfile_text, re.M):
        c.error("Containerfile", "FROM is not localhost/fedsim-base:bookworm (build-base-image.sh's tag)")
    services = compose["services"]
    for name, svc in services.items():
        argv = [interpolate_default(str(w)) for w in svc["command"]]
        env = {**base_env, **{k: str(v) for k, v in (svc.get("environment") or {}).items()}}
        c.check_command(f"compose.yaml: services.{name}", argv, env)
    # Same federates and arguments as deploy/default.yaml.
    lockstep = [n for n in services if n not in NOT_LOCKSTEP and n != "timing"]
    for fed in default["federates"]:
        name = fed["name"]
        if name not in services:
            continue  # e.g. the image generator, left out of the containers
        want = [fed["binary"]] + [str(a).replace("${DATA_DIR}", "/opt/fedsim/data")
                                  .replace("${OUT_DIR}", "/opt/fedsim/out") for a in fed.get("args", [])]
        got = strip([interpolate_default(str(w)) for w in services[name]["command"]], name)
        if name == "recorder":
            i = got.index("--participant-profile")
            got = got[:i] + got[i + 2:]
        if got != want and name not in DEFAULT_EXCEPTIONS:
            c.error(f"compose.yaml: services.{name}", f"differs from deploy/default.yaml:\n  {got}\n  {want}")
    timing = [interpolate_default(str(w)) for w in services["timing"]["command"]]
    expect = timing[timing.index("--expect") + 1].split(",")
    if sorted(expect) != sorted(lockstep):
        c.error("compose.yaml: services.timing", f"--expect {expect} is not the lockstep services {lockstep}")
    if float(timing[timing.index("--rate") + 1]) != float(default["rate_hz"]):
        c.error("compose.yaml: services.timing", "--rate differs from deploy/default.yaml's rate_hz")
    if timing[timing.index("--frames") + 1] != str(default["timing"]["args"][1]):
        c.error("compose.yaml: services.timing", "--frames default differs from deploy/default.yaml")
    # Kubernetes: a Deployment per service, same command and environment.
    deployments = {d["metadata"]["name"]: d for d in k8s_docs if d and d["kind"] == "Deployment"}
    k8s_services = {d["metadata"]["name"]: d for d in k8s_docs if d and d["kind"] == "Service"}
    for name, svc in services.items():
        dname = "fedsim-" + name.replace("_", "-")
        if dname not in deployments:
            c.error("k8s/fedsim.yaml", f"no Deployment {dname} for compose service {name}")
            continue
        container = deployments[dname]["spec"]["template"]["spec"]["containers"][0]
        if container["image"] != svc.get("image", "localhost/fedsim:latest"):
            c.error(f"k8s/fedsim.yaml: {dname}", "image differs from compose.yaml")
        want = [interpolate_default(str(w)) for w in svc["command"]]
        if name == "timing":  # realtime, no frame limit, no shutdown: a Deployment restarts what exits
            i = want.index("--frames"); del want[i:i + 2]
            want.remove("--shutdown-on-exit")
            want[want.index("lockstep")] = "realtime"
        if container["command"] != want:
            c.error(f"k8s/fedsim.yaml: {dname}", f"command differs from compose.yaml:\n  {container['command']}\n  {want}")
        k8s_env = {e["name"]: e.get("value", "<secret>") for e in container.get("env", [])}
        compose_env = {k: str(v) for k, v in (svc.get("environment") or {}).items()}
        if set(k8s_env) != set(compose_env) or any(
                k8s_env[k] != v for k, v in compose_env.items() if k8s_env[k] != "<secret>"):
            c.error(f"k8s/fedsim.yaml: {dname}", f"environment {k8s_env} differs from compose.yaml {compose_env}")
        c.check_command(f"k8s/fedsim.yaml: {dname}", container["command"], {**base_env, **k8s_env})
    for sname, port, proto in (("discovery", 11811, "UDP"), ("fedsim-ios", 8470, "TCP")):
        s = k8s_services.get(sname)
        if not s:
            c.error("k8s/fedsim.yaml", f"no Service {sname}")
            continue
        target = s["spec"]["selector"].get("app.kubernetes.io/name")
        if target not in deployments:
            c.error(f"k8s/fedsim.yaml: Service {sname}", f"selects no Deployment ({target})")
        p = s["spec"]["ports"][0]
        if (p["port"], p["protocol"]) != (port, proto):
            c.error(f"k8s/fedsim.yaml: Service {sname}", f"port {p} is not {port}/{proto}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--source", required=True)
    a = ap.parse_args()
    here = os.path.join(a.source, "deploy/containers")
    compose = yaml.safe_load(open(os.path.join(here, "compose.yaml")))
    k8s = list(yaml.safe_load_all(open(os.path.join(here, "k8s/fedsim.yaml"))))
    default = yaml.safe_load(open(os.path.join(a.source, "deploy/default.yaml")))
    containerfile = open(os.path.join(here, "Containerfile")).read()

    c = Checker(os.path.abspath(a.bin), os.path.abspath(a.source))
    check_all(c, compose, k8s, default, containerfile)
    for e in c.errors:
        print("containers check: ERROR", e)
    # Negative control: an option the flight federate does not have must be caught.
    bad = copy.deepcopy(compose)
    bad["services"]["flight"]["command"] = list(bad["services"]["flight"]["command"]) + ["--no-such-option", "1"]
    nc = Checker(os.path.abspath(a.bin), os.path.abspath(a.source))
    check_all(nc, bad, k8s, default, containerfile)
    if not any("--no-such-option" in e for e in nc.errors):
        print("containers check: ERROR negative control: an unknown option was not caught")
        c.errors.append("negative control")
    else:
        print("containers check: negative control caught:", next(e for e in nc.errors if "--no-such-option" in e).splitlines()[0])
    if c.errors:
        return 1
    print(f"containers check: {len(compose['services'])} services, "
          f"{sum(1 for d in k8s if d)} Kubernetes objects: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
