# Sourced by the scripts of scripts/: the help of a script is its opening comment (the lines
# after "#!" up to the first line that is not a comment), which starts with its usage.
#   print_help SCRIPT       prints that comment without the "# "
#   exit_if_help_asked ARG...   prints the help of $0 and exits with 0 when -h or --help is among
#                           ARG..., before the script does anything
print_help() {
  sed -n '2,/^[^#]/{/^#/{s/^# \{0,1\}//;p}}' "$1"
}
exit_if_help_asked() {
  local arg
  for arg in "$@"; do
    case $arg in
      -h|--help) print_help "$0"; exit 0 ;;
    esac
  done
}
