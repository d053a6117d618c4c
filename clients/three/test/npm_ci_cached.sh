#!/usr/bin/env bash
# Installs a client's pinned npm packages (package-lock.json) into its node_modules (clients/three by default)
# with `npm ci`, once: a stamp holding the lock file's SHA-256 skips the install while the
# lock file is unchanged. flock keeps concurrent test processes from installing at once.
# Exit status: 0 ready; 2 no npm or the install failed (message on stderr).
set -euo pipefail
# The client folder: the first argument (clients/webgpu uses this script too), else this script's client.
client="$(cd "${1:-$(dirname "$0")/..}" && pwd)"
command -v npm >/dev/null ||
  { echo "npm_ci_cached: npm not found: install Node.js 20+ with npm (the CI machine has both)" >&2; exit 2; }
exec 9>"$client/.npm-ci.lock"
flock 9
want=$(sha256sum "$client/package-lock.json" | cut -d' ' -f1)
stamp="$client/node_modules/.watergraph-lock-sha256"
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ]; then exit 0; fi
if ! (cd "$client" && npm ci --no-audit --no-fund --loglevel=error >&2); then
  echo "npm_ci_cached: \`npm ci\` failed in $client (it needs the npm registry)" >&2
  exit 2
fi
echo "$want" >"$stamp"
