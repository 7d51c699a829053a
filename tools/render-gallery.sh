#!/usr/bin/env bash
# Renders the gallery (docs/gallery/NAME.png, 400x300) from the scenes listed in
# docs/GALLERY.md with the sample counts written there, and prints each render's summary
# line to bring the page's figures up to date. Takes about an hour and a half on 2 cores.
#   tools/render-gallery.sh [NAME ...]     (default: every scene on the page)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/tools/build.sh" >/dev/null
# "NAME SPP" for each "### `scenes/NAME.in`" heading and the "N spp, ..." line under it.
mapfile -t entries < <(awk '/^### `scenes\//{gsub(/### `scenes\//,""); gsub(/\.in`/,""); name=$0}
                            /^[0-9]+ spp/ && name != "" {print name, $1}' "$root/docs/GALLERY.md")
for entry in "${entries[@]}"; do
    read -r name spp <<<"$entry"
    if [ $# -gt 0 ] && [[ ! " $* " == *" $name "* ]]; then
        continue
    fi
    echo -n "$name: "
    "$root/build/raytracer" "$root/scenes/$name.in" 400 300 --spp "$spp" --headless --quiet \
        --output "$root/docs/gallery/$name.png"
done
