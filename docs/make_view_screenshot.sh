#!/bin/sh
# Makes docs/tilted_disk_view.png, the README's screenshot of `eulerdyn view`: the browser tests open the tilted
# disk's page in headless Chromium and save the view at t = 0.3 s. Needs /usr/bin/chromium. Run from the
# repository root:
#   sh docs/make_view_screenshot.sh
set -eu
EULERDYN_VIEW_SCREENSHOT="$PWD/docs/tilted_disk_view.png" .ci/browser-tests -k "not_blank and disk"
