#!/usr/bin/env bash
# A fixed CPU yardstick (issue 14), so that benchmark times can be compared
# across machines: an AES-128-CTR keystream of 64 MiB (openssl) through
# gzip -6, about 1.8 s on the 2-core development machine when idle. Prints
# the median wall time of three runs in seconds.
set -eu  # (no pipefail: head ends the keystream with SIGPIPE)
times=()
for i in 1 2 3; do
  t0=$(date +%s.%N)
  openssl enc -aes-128-ctr -nosalt -pass pass:qsmpm -pbkdf2 -in /dev/zero 2>/dev/null |
    head -c 67108864 | gzip -6 > /dev/null
  times+=("$(echo "$(date +%s.%N) - $t0" | bc -l)")
done
printf '%s\n' "${times[@]}" | sort -g | sed -n 2p
