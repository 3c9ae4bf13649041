#!/usr/bin/env bash
# Rebuilds three.bundle.min.js (the renderer embedded in every replay page)
# from the exact versions in package-lock.json: three 0.187.0 (MIT) and the
# bundler esbuild 0.28.2. Needs Node.js and npm; run it after changing
# entry.js or the pinned versions, and commit the bundle and the licence.
# The pegdyn build itself never runs this: the bundle is committed and
# included into the binary with include_str!.
set -euo pipefail
cd "$(dirname "$0")"
npm ci --no-audit --no-fund --ignore-scripts
version=$(node -p "JSON.parse(require('fs').readFileSync('node_modules/three/package.json', 'utf8')).version")
npx esbuild entry.js --bundle --minify --format=iife --global-name=PegdynThree \
  --legal-comments=none \
  --banner:js="/* three.js ${version} (https://threejs.org, MIT licence: LICENSE-three.txt), the parts the pegdyn replay page uses, bundled by assets/replay/build.sh */" \
  --outfile=three.bundle.min.js
cp node_modules/three/LICENSE LICENSE-three.txt
echo "three.bundle.min.js: three ${version}, $(wc -c < three.bundle.min.js) bytes"
