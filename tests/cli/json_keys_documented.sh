#!/usr/bin/env bash
# Every key of a flat, a cluster, a deadlock, an animation and a moving scene's JSON report is in docs/report.md's key table (or
# its Cluster keys section), and every key the table lists unconditionally is written.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
f="$SRC/scenes/paper-image1.nff"
sim=("$BUILD/torusrt-sim" "$f" -q --t1 1 --size 16x16)
"${sim[@]}" -o "$TMP/flat.png" --stats "$TMP/flat.json" --ips 2x2 || fail "flat run"
"${sim[@]}" -o "$TMP/cl.png" --stats "$TMP/cl.json" --ips 2 --cluster 3 --data shared || fail "cluster run"
"${sim[@]}" -o "$TMP/dl.png" --stats "$TMP/dl.json" --ips 1 --queue 1 --flow none 2> /dev/null
check "the deadlock run exits 3" test $? -eq 3
"$BUILD/torusrt-sim" "$f" -q --size 16x16 -o "$TMP/an_%d.png" --stats "$TMP/an.json" --ips 2 --frames 3 --orbit 10 \
    --remap adaptive ||
    fail "animation run"
sed 's/^frames 64$/frames 2/' "$SRC/scenes/bouncing-balls.motion" >"$TMP/balls.motion"
"$BUILD/torusrt-sim" "$SRC/scenes/bouncing-balls.nff" -q --size 16x16 -o "$TMP/mo_%d.png" --stats "$TMP/mo.json" \
    --ips 2 --motion "$TMP/balls.motion" || fail "motion run"
python3 - "$SRC/docs/report.md" "$TMP/flat.json" "$TMP/cl.json" "$TMP/dl.json" "$TMP/an.json" "$TMP/mo.json" \
    > "$TMP/keys.txt" <<'PY'
import json, re, sys
readme = open(sys.argv[1]).read()
table = readme[readme.index("## The JSON report of `torusrt-sim`"):readme.index("## Cluster keys")]
cluster = readme[readme.index("## Cluster keys"):readme.index("## Reading the two efficiencies")]
def expand(s):  # a.{b,c{d,e}} -> a.b, a.c.d, a.c.e
    i = s.find("{")
    if i < 0:
        return [s]
    depth, parts, start = 0, [], i + 1
    for j in range(i, len(s)):
        depth += {"{": 1, "}": -1}.get(s[j], 0)
        if depth == 1 and s[j] == ",":
            parts.append(s[start:j]); start = j + 1
        if depth == 0:
            parts.append(s[start:j]); break
    head = s[:i] if s[:i].endswith(".") or not s[:i] else s[:i] + "."
    return [x for p in parts for x in expand(head + p.strip() + s[j + 1:])]
table_keys = {x for row in table.splitlines() if row.startswith("| `")
              for tok in re.findall(r"`([^`]*)`", row.split("|")[1]) for x in expand(tok)}
keys = set()  # the table's key column and the Clusters paragraph
for text in [row.split("|")[1] for row in table.splitlines() if row.startswith("| `")] + [cluster]:
    for tok in re.findall(r"`([^`]*)`", text):
        keys.update(expand(tok))
words = set(re.findall(r"`([a-z_]+)`", table + cluster)) | {c.replace("[]", "") for k in keys for c in k.split(".")}
def paths(v, p=""):
    if isinstance(v, dict):
        for k, x in v.items():
            q = p + "." + k if p else k
            yield q
            if not q.startswith("config.") and not p.endswith("[]"):
                yield from paths(x, q)
    elif isinstance(v, list) and v and not p.endswith("[]"):
        yield from paths(v[0], p + "[]")
def documented(p):
    if "[]." in p:
        return p.rsplit("[].", 1)[1] in words
    parts = p.split(".")
    for i in range(len(parts), 0, -1):
        pre = ".".join(parts[:i])
        if pre in keys or pre + ".*" in keys or pre + "[]" in keys:
            return True
    return any(k.startswith(p + ".") or k.startswith(p + "[]") for k in keys)
seen = set()
for name in sys.argv[2:]:
    for p in paths(json.load(open(name))):
        seen.add(p.replace("[]", ""))
        if not documented(p):
            print("undocumented: %s (%s)" % (p, name.rsplit("/", 1)[-1]))
for k in sorted(table_keys):  # the table's keys but those written only by --map cost or --map-file
    if re.fullmatch(r"[a-z_.\[\]]+", k) and not k.startswith("mapping.") and k.replace("[]", "") not in seen:
        print("documented but never written: %s" % k)
PY
check "the key check ran" test $? -eq 0
check "every key documented, every documented key written: $(tr '\n' ' ' < "$TMP/keys.txt")" test ! -s "$TMP/keys.txt"
finish
