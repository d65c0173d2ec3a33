#!/usr/bin/env bash
# Writes DIR/SHA256SUMS: the SHA-256 of every file under DIR but SHA256SUMS itself (README.md too),
# by path relative to DIR, sorted. Check a download with: cd DIR && sha256sum -c SHA256SUMS
#   bash scripts/checksums.sh DIR
set -euo pipefail
cd "$1"
sums=$(mktemp)
find . -type f ! -path ./SHA256SUMS -printf '%P\n' | LC_ALL=C sort |
  while IFS= read -r file; do sha256sum -- "$file"; done >"$sums"
mv "$sums" SHA256SUMS
chmod 644 SHA256SUMS
