#!/usr/bin/env bash
# Makes the DDS Security credentials of a fedsim federation (docs/security.md):
#   OUTDIR/identity_ca.pem        identity CA certificate (signs every participant's certificate)
#   OUTDIR/permissions_ca.pem     permissions CA certificate (signs governance and permissions)
#   OUTDIR/ca/*.key               the two CAs' private keys (keep them off the federation's hosts)
#   OUTDIR/governance.p7s         signed governance (governance.xml: the readable copy)
#   OUTDIR/NAME/cert.pem key.pem  each identity's certificate (subject O=fedsim, CN=NAME) and key
#   OUTDIR/NAME/permissions.p7s   its signed grant (permissions.xml: the readable copy)
# Two CAs, both made here: whoever may admit a host (identity CA) need not be who decides what it
# may write (permissions CA). Run again on the same OUTDIR to add or re-issue identities: the CAs
# already there are kept, so the credentials issued before stay valid.
#
# Grant policy (deploy/security/permissions.xml.in): every identity reads every fedsim/* topic and
# writes every fedsim/* topic except the protected ones, fedsim/sim_command (instructor commands)
# and fedsim/pilot_controls (the aircraft's controls), which it writes only with the grant
# "command" or "controls". "readonly" writes nothing. Anything outside fedsim/* is denied.
#
# Certificates and keys: EC P-256 (prime256v1), SHA-256, made with openssl; signatures with
# `openssl smime -sign -text` (the S/MIME form Fast DDS's builtin.Access-Permissions reads).
set -euo pipefail
shopt -u patsub_replacement 2>/dev/null || true  # bash 5.2: '&' in ${x//p/r} stays an '&'

SCRIPT_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
readonly SCRIPT_DIR
readonly PROTECTED_COMMAND="fedsim/sim_command"
readonly PROTECTED_CONTROLS="fedsim/pilot_controls"
readonly NAME_PATTERN='^[A-Za-z0-9_][A-Za-z0-9_.-]*$'  # same rule as common/runtime/dds_participant.cpp

usage() {
  cat <<EOF
usage: $(basename "$0") [--days N] [--domains MIN-MAX] [--deployment FILE] OUTDIR [NAME[:GRANT[,GRANT]]...]

Makes an identity CA and a permissions CA (kept if OUTDIR has them already), the signed
governance, and for every NAME a certificate (CN=NAME), its key and its signed permissions.
NAME is a federate's --name (or the FEDSIM_SECURITY_IDENTITY a tool runs as).
GRANT: command   may also write $PROTECTED_COMMAND (timing, ios, scenario, the fedsim command tool)
       controls  may also write $PROTECTED_CONTROLS (io, an external trainer)
       readonly  writes nothing (monitors)
Without a grant an identity writes every other fedsim/* topic and reads all of them.
  --days N          validity of certificates and permissions, 1..36500 days (default 365)
  --domains MIN-MAX DDS domains the governance and grants cover, within 0-232 (default 0-232)
  --deployment FILE also every identity a \`fedsim run FILE\` needs, from \`fedsim graph FILE\`:
                    each federate (controls if it writes $PROTECTED_CONTROLS, command for
                    fedsim-ios and fedsim-scenario), timing:command, a recorder's NAME-data
                    participant (readonly) and the launcher's monitor fedsim-run:readonly
                    (the fedsim program: \$FEDSIM_BIN, else build/bin/fedsim, else PATH)
Example: $(basename "$0") secrets timing:command flight io:controls recorder instructor:command
         $(basename "$0") --deployment deploy/default.yaml secrets instructor:command
EOF
}

fail() {
  echo "make-security.sh: $*" >&2
  exit 2
}

days=365
deployment=""
domain_min=0
domain_max=232
while [[ $# -gt 0 ]]; do
  case "$1" in
    -h|--help) usage; exit 0 ;;
    --days)
      [[ $# -ge 2 ]] || fail "--days needs a value"
      if ! [[ "$2" =~ ^[0-9]{1,5}$ ]] || (( 10#$2 < 1 || 10#$2 > 36500 )); then
        fail "--days '$2' is not a whole number of days in 1..36500"
      fi
      days=$((10#$2)); shift 2 ;;
    --domains)
      [[ $# -ge 2 ]] || fail "--domains needs a value MIN-MAX"
      [[ "$2" =~ ^([0-9]{1,3})-([0-9]{1,3})$ ]] || fail "--domains '$2' is not MIN-MAX (e.g. 0-232)"
      domain_min=$((10#${BASH_REMATCH[1]})); domain_max=$((10#${BASH_REMATCH[2]}))
      (( domain_min <= domain_max && domain_max <= 232 )) ||
        fail "--domains '$2': need MIN <= MAX <= 232 (Fast DDS's highest domain id)"
      shift 2 ;;
    --deployment)
      [[ $# -ge 2 ]] || fail "--deployment needs a deployment file"
      [[ -f "$2" ]] || fail "--deployment: no such file '$2'"
      deployment="$2"; shift 2 ;;
    --) shift; break ;;
    -*) fail "unknown option '$1' (see --help)" ;;
    *) break ;;
  esac
done
[[ $# -ge 1 ]] || { usage >&2; fail "missing OUTDIR"; }
outdir="$1"; shift
[[ -n "$outdir" ]] || fail "OUTDIR is empty"
command -v openssl >/dev/null || fail "openssl not found (Debian package openssl)"

# identities_of_deployment FILE: the NAME:GRANTS a `fedsim run FILE` needs, read from the text
# `fedsim graph` prints ("  NAME (BINARY ...)" per federate, the timing federate included,
# "    writes TOPIC ..." per port, up to "data flow:"): a writer of the protected controls gets
# "controls", a writer of fedsim/sim_command (the timing federate's command holder, the
# instructor station, a scenario) gets "command".
identities_of_deployment() {
  local fedsim="${FEDSIM_BIN:-}"
  if [[ -z "$fedsim" ]]; then
    fedsim="$SCRIPT_DIR/../../build/bin/fedsim"
    [[ -x "$fedsim" ]] || fedsim="$(command -v fedsim || true)"
  fi
  [[ -n "$fedsim" && -x "$fedsim" ]] ||
    fail "--deployment needs the fedsim program: set FEDSIM_BIN (not found in build/bin or PATH)"
  local graph
  graph="$("$fedsim" graph "$1" 2>/dev/null)" || fail "fedsim graph $1 failed: $("$fedsim" graph "$1" 2>&1 | tail -n 3)"
  awk -v controls="$PROTECTED_CONTROLS" '
    function flush() {
      if (name == "") return
      g = ""
      if (writes_controls) g = "controls"
      if (writes_commands) g = (g == "" ? "" : g ",") "command"
      print (g == "" ? name : name ":" g)
      if (binary == "fedsim record") print name "-data:readonly"  # its second participant
      name = ""
    }
    done { next }
    /^data flow:/ { flush(); done = 1; next }
    /^  [^ ].* \(.*\)$/ {
      flush(); name = $1; binary = $0; sub(/^[^(]*\(/, "", binary); sub(/\)$/, "", binary)
      writes_controls = 0; writes_commands = 0; next
    }
    /^    writes / { if ($2 == controls) writes_controls = 1; if ($2 == "fedsim/sim_command") writes_commands = 1; next }
    /^[^ ]/ { flush() }
    END { flush() }' <<<"$graph"
  echo "fedsim-run:readonly"
}

if [[ -n "$deployment" ]]; then
  mapfile -t from_deployment < <(identities_of_deployment "$deployment")
  [[ ${#from_deployment[@]} -gt 1 ]] || fail "--deployment $deployment: fedsim graph listed no federate"
  set -- "${from_deployment[@]}" "$@"
fi
[[ $# -ge 1 ]] || fail "no identity named: give at least one NAME (a federate's --name) or --deployment"

# Checks every NAME[:GRANTS] before making anything, so a typo leaves OUTDIR untouched.
declare -A grants_of=()
names=()
for spec in "$@"; do
  name="${spec%%:*}"
  grants=""
  [[ "$spec" == *:* ]] && grants="${spec#*:}"
  [[ "$name" =~ $NAME_PATTERN ]] ||
    fail "identity '$name' is not a plain name (letters, digits, '_', '-', '.'; not starting with '.' or '-')"
  [[ "$name" != ca ]] || fail "identity 'ca' is reserved (OUTDIR/ca holds the CA keys)"
  [[ -z "${grants_of[$name]+x}" ]] || fail "identity '$name' is named twice"
  if [[ "$spec" == *: ]]; then fail "identity '$name': empty grant list after ':'"; fi
  IFS=',' read -r -a list <<<"$grants"
  for g in "${list[@]}"; do
    case "$g" in
      command|controls|readonly) ;;
      *) fail "identity '$name': unknown grant '$g' (command, controls, readonly)" ;;
    esac
  done
  if [[ ",$grants," == *,readonly,* && "$grants" != readonly ]]; then
    fail "identity '$name': readonly cannot be combined with another grant"
  fi
  grants_of[$name]="$grants"
  names+=("$name")
done

mkdir -p "$outdir/ca"
chmod 700 "$outdir/ca"
umask 077  # keys readable by their owner only

# make_ca KIND "Common Name": OUTDIR/KIND_ca.pem and OUTDIR/ca/KIND_ca.key, unless both exist.
# digitalSignature: the permissions CA signs the S/MIME documents itself, and OpenSSL's
# PKCS7_verify (Fast DDS's check) refuses a signer without it ("unsuitable certificate purpose").
make_ca() {
  local kind="$1" cn="$2"
  local cert="$outdir/${kind}_ca.pem" key="$outdir/ca/${kind}_ca.key"
  if [[ -f "$cert" && -f "$key" ]]; then
    echo "keeping the $kind CA in $cert"
    return
  fi
  [[ ! -e "$cert" && ! -e "$key" ]] ||
    fail "$kind CA incomplete: one of $cert and $key exists without the other (remove it or restore both)"
  openssl ecparam -name prime256v1 -genkey -noout -out "$key"
  openssl req -x509 -new -key "$key" -sha256 -days "$days" -subj "/O=fedsim/CN=$cn" \
    -addext "basicConstraints=critical,CA:TRUE" \
    -addext "keyUsage=critical,digitalSignature,keyCertSign,cRLSign" \
    -out "$cert"
  chmod 644 "$cert"
  echo "made the $kind CA: $cert"
}

# sign_smime IN OUT: S/MIME signature by the permissions CA, the text kept readable inside.
sign_smime() {
  openssl smime -sign -text -in "$1" -out "$2" \
    -signer "$outdir/permissions_ca.pem" -inkey "$outdir/ca/permissions_ca.key"
  chmod 644 "$1" "$2"
}

# fill TEMPLATE KEY=VALUE...: the template with every @KEY@ replaced (values may hold newlines).
fill() {
  local text pair
  text="$(<"$1")"; shift
  for pair in "$@"; do text="${text//@${pair%%=*}@/${pair#*=}}"; done
  if [[ "$text" =~ @[A-Z_]+@ ]]; then fail "template has an unfilled ${BASH_REMATCH[0]}"; fi
  printf '%s\n' "$text"
}

domains_xml="<domains><id_range><min>$domain_min</min><max>$domain_max</max></id_range></domains>"

# rules_for GRANTS: the permission rules of deploy/security/permissions.xml.in's policy.
rules_for() {
  local grants=",$1,"
  if [[ "$grants" == *,readonly,* ]]; then
    cat <<EOF
      <allow_rule>
        $domains_xml
        <subscribe><topics><topic>fedsim/*</topic></topics></subscribe>
      </allow_rule>
EOF
    return
  fi
  local denied=()
  [[ "$grants" == *,command,* ]] || denied+=("$PROTECTED_COMMAND")
  [[ "$grants" == *,controls,* ]] || denied+=("$PROTECTED_CONTROLS")
  if [[ ${#denied[@]} -gt 0 ]]; then
    echo "      <deny_rule>"
    echo "        $domains_xml"
    echo -n "        <publish><topics>"
    for t in "${denied[@]}"; do echo -n "<topic>$t</topic>"; done
    echo "</topics></publish>"
    echo "      </deny_rule>"
  fi
  cat <<EOF
      <allow_rule>
        $domains_xml
        <publish><topics><topic>fedsim/*</topic></topics></publish>
        <subscribe><topics><topic>fedsim/*</topic></topics></subscribe>
      </allow_rule>
EOF
}

make_ca identity "fedsim identity CA"
make_ca permissions "fedsim permissions CA"

fill "$SCRIPT_DIR/governance.xml.in" DOMAIN_MIN="$domain_min" DOMAIN_MAX="$domain_max" \
  >"$outdir/governance.xml"
sign_smime "$outdir/governance.xml" "$outdir/governance.p7s"

not_before="$(date -u -d '-1 hour' +%Y-%m-%dT%H:%M:%S)"  # an hour's slack for clocks behind
not_after="$(date -u -d "+$days days" +%Y-%m-%dT%H:%M:%S)"
for name in "${names[@]}"; do
  dir="$outdir/$name"
  mkdir -p "$dir"
  openssl ecparam -name prime256v1 -genkey -noout -out "$dir/key.pem"
  openssl req -new -key "$dir/key.pem" -subj "/O=fedsim/CN=$name" -out "$dir/cert.csr"
  openssl x509 -req -in "$dir/cert.csr" -CA "$outdir/identity_ca.pem" \
    -CAkey "$outdir/ca/identity_ca.key" -set_serial "0x$(openssl rand -hex 16)" -days "$days" \
    -sha256 -out "$dir/cert.pem" 2>/dev/null
  rm -f "$dir/cert.csr"
  chmod 644 "$dir/cert.pem"
  fill "$SCRIPT_DIR/permissions.xml.in" NAME="$name" SUBJECT="CN=$name,O=fedsim" \
    NOT_BEFORE="$not_before" NOT_AFTER="$not_after" RULES="$(rules_for "${grants_of[$name]}")" \
    >"$dir/permissions.xml"
  sign_smime "$dir/permissions.xml" "$dir/permissions.p7s"
  echo "made identity '$name' (grants: ${grants_of[$name]:-none}) in $dir"
done
