# Sourced by the architecture checks of the studio's sources.
# only_in DIR ERE ALLOWED WHY: every .cpp and .h below DIR whose text matches
# the extended regular expression ERE must be one of ALLOWED (paths relative
# to DIR, one a line); each other fails with WHY and its matching lines.
# Sets `status` (1 on a failure) and `found` (the matching files).
only_in() {
    dir=$1 ere=$2 allowed=$3 why=$4
    status=0
    found=$(cd "$dir" && grep -rlE "$ere" --include='*.cpp' --include='*.h' . | sed 's|^\./||' | sort)
    for f in $found; do
        case "$allowed" in
        *"
$f
"*) ;;
        *)
            echo "FAIL: $f $why"
            (cd "$dir" && grep -nE "$ere" "$f")
            status=1
            ;;
        esac
    done
}
