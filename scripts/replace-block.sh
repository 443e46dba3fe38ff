# Sourced by the benchmark scripts.
# replace_block FILE NAME BODY: replaces the lines between "<!-- BEGIN NAME -->" and
# "<!-- END NAME -->" of FILE with the contents of the file BODY (appends the block when the
# markers are missing).
replace_block() {
  local file=$1 name=$2 body=$3 begin="<!-- BEGIN $2 -->" end="<!-- END $2 -->"
  [ -f "$file" ] || : > "$file"
  if ! grep -qF "$begin" "$file"; then
    printf '\n%s\n%s\n' "$begin" "$end" >> "$file"
  fi
  awk -v b="$begin" -v e="$end" -v body="$body" '
    $0 == b { print; while ((getline line < body) > 0) print line; skip = 1; next }
    $0 == e { skip = 0 }
    !skip { print }' "$file" > "$file.tmp"
  mv "$file.tmp" "$file"
}
