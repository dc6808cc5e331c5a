#!/bin/sh
# A stand-in for Chromium (issue 39): writes a one-line "PDF" where
# --print-to-pdf= asks, with shell built-ins only, so that it runs with a PATH
# that holds no other program (no `timeout`, no pdftohtml, no qpdf).
for a in "$@"; do
  case "$a" in
    --print-to-pdf=*) printf '%%PDF-1.4\n%% a stand-in for Chromium\n' > "${a#--print-to-pdf=}" ;;
  esac
done
exit 0
