# launcher.sh: the one launcher logic of the tracer, sourced by ./tracer (the source tree) and by
# bin/tracer (the installed distribution); not run by itself. It chooses the Java to run, keeps
# the start-up cache for that Java and the jar, and starts the tracer (docs/install.md, "How the
# launcher starts Java", tells the same for users).
#
#   tracer_launch JAR TRAINING_DIR... -- ARGS...
#
# JAR is the tracer's jar. Every *.xml in the TRAINING_DIRs is a scene of the cache's training run.
#
# Environment:
#   TRACER_JAVA       the Java to run: a `java` program or the home directory of a JDK or JRE;
#                     when unset the launcher chooses (tracer_choose_java)
#   TRACER_JAVA_OPTS  the JVM's options, replacing the default
#                     "-Xss8m -XX:+UseSerialGC -XX:LoopUnrollLimit=1
#                     -XX:Tier2BackedgeNotifyFreqLog=30" (and the default's quick
#                     end: -Dtracer.exit=halt)
#   TRACER_CACHE      "off": no start-up cache; "cds": an AppCDS archive even on JDK 25 or newer
#                     (for comparisons); anything else (or unset): the cache below
#   TRACER_JDK_DIRS   where installed JDKs are looked for (default "/usr/lib/jvm"), a list
#                     separated by ':'
#   TRACER_LANES      "on": the ray kernel tests four boxes at once with the Vector API (faster
#                     renders of many shapes, a slower start); "off" (or unset): one at a time
# shellcheck shell=bash

# The oldest Java the tracer runs on (the jar's class files are Java 17's).
readonly tracer_min_java=17

# The width the AOT cache's training run renders its scenes at: the method profiles of 960-pixel
# renders start users' short renders about 10% sooner than those of 320-pixel ones, for a training
# of about 15 s instead of 6 (docs/performance.md, round 13). Part of the cache's name.
readonly tracer_training_width=960

# The JVM's options when TRACER_JAVA_OPTS is unset (tracer_launch says why each); scripts/ab.sh
# and scripts/startup-bench.sh read them from here.
readonly tracer_default_jvm='-Xss8m -XX:+UseSerialGC -XX:LoopUnrollLimit=1 -XX:Tier2BackedgeNotifyFreqLog=30'

# tracer_release_version HOME: prints JAVA_VERSION from the JDK's HOME/release file (e.g. 25.0.3),
# or fails when there is none. Reads the file in the shell: no process is started.
tracer_release_version() {
  local line
  [ -r "$1/release" ] || return 1
  while IFS= read -r line || [ -n "$line" ]; do
    case "$line" in
      JAVA_VERSION=*)
        line=${line#JAVA_VERSION=}
        line=${line//\"/}
        [ -n "$line" ] || return 1
        printf '%s\n' "$line"
        return 0
        ;;
    esac
  done <"$1/release"
  return 1
}

# tracer_feature VERSION: the feature release of a Java version string (17.0.15 -> 17,
# 25 -> 25, 25-ea -> 25, 1.8.0_392 -> 8); 0 when it is not a version.
tracer_feature() {
  local v=$1 major
  case "$v" in 1.*) v=${v#1.} ;; esac
  major=${v%%[!0-9]*}
  printf '%s\n' "${major:-0}"
}

# tracer_choose_java: sets tracer_java (the java program to run), tracer_java_home,
# tracer_java_version (empty when unknown) and tracer_java_feature (0 when unknown).
#
# TRACER_JAVA wins when set. Otherwise the candidates are, in this order, JAVA_HOME, the `java` on
# PATH and every JDK in TRACER_JDK_DIRS (default /usr/lib/jvm, where Linux distributions put
# them); the newest feature release of at least 17 wins, and among equals the earlier candidate
# (so JAVA_HOME, then PATH, keep their say). A version is read from the JDK's `release` file. A
# Java without one is taken only when no candidate of a known version qualifies. Fails with one
# line on stderr when no Java is found or only ones older than 17.
tracer_choose_java() {
  local candidates=() dirs dir entry found
  tracer_java='' tracer_java_home='' tracer_java_version='' tracer_java_feature=0
  if [ -n "${TRACER_JAVA:-}" ]; then
    entry=$TRACER_JAVA
    if [ -d "$entry" ]; then entry=$entry/bin/java; fi
    if [ ! -x "$entry" ]; then
      echo "tracer: TRACER_JAVA='$TRACER_JAVA' is not a java program or a Java home" >&2
      return 1
    fi
    tracer_take_java "$entry"
    return 0
  fi
  if [ -n "${JAVA_HOME:-}" ] && [ -x "$JAVA_HOME/bin/java" ]; then candidates+=("$JAVA_HOME/bin/java"); fi
  if found=$(command -v java 2>/dev/null) && [ -n "$found" ]; then candidates+=("$found"); fi
  IFS=: read -r -a dirs <<<"${TRACER_JDK_DIRS:-/usr/lib/jvm}"
  for dir in ${dirs[@]+"${dirs[@]}"}; do
    for entry in "$dir"/*/bin/java; do
      if [ -x "$entry" ]; then candidates+=("$entry"); fi
    done
  done
  if [ ${#candidates[@]} -eq 0 ]; then
    echo "tracer: no Java found: install a Java runtime of version $tracer_min_java or newer, or set TRACER_JAVA" >&2
    return 1
  fi
  local real=() best='' best_feature=0 unknown='' i home version feature line
  # One readlink for all: each candidate's real path, where its release file is.
  while IFS= read -r line; do real+=("$line"); done < <(readlink -f -- "${candidates[@]}" 2>/dev/null)
  # A path readlink cannot resolve (or one with a newline) would shift the others' lines: then
  # trust none of them, and each chosen Java is looked up again.
  if [ "${#real[@]}" -ne "${#candidates[@]}" ]; then real=(); fi
  local best_real='' unknown_real=''
  for i in "${!candidates[@]}"; do
    home=${real[$i]:-${candidates[$i]}}
    home=${home%/bin/java}
    if version=$(tracer_release_version "$home"); then
      feature=$(tracer_feature "$version")
      if [ "$feature" -ge "$tracer_min_java" ] && [ "$feature" -gt "$best_feature" ]; then
        best=${candidates[$i]} best_real=${real[$i]:-} best_feature=$feature
      fi
    elif [ -z "$unknown" ]; then
      unknown=${candidates[$i]} unknown_real=${real[$i]:-}
    fi
  done
  if [ -n "$best" ]; then
    tracer_take_java "$best" "$best_real"
  elif [ -n "$unknown" ]; then
    tracer_take_java "$unknown" "$unknown_real"
  else
    echo "tracer: needs Java $tracer_min_java or newer; found only older ones (set TRACER_JAVA to a newer one)" >&2
    return 1
  fi
}

# tracer_take_java JAVA [REAL]: sets tracer_java and what is known of its version; REAL is JAVA's
# real path when the caller has it already (else it is looked up).
tracer_take_java() {
  local real=${2:-}
  tracer_java=$1
  if [ -z "$real" ]; then real=$(readlink -f -- "$1" 2>/dev/null) || real=$1; fi
  tracer_java_home=${real%/bin/java}
  if tracer_java_version=$(tracer_release_version "$tracer_java_home"); then
    tracer_java_feature=$(tracer_feature "$tracer_java_version")
  else
    tracer_java_version='' tracer_java_feature=0
  fi
}

# tracer_java_flags: sets tracer_flags, the options every start of this Java needs besides
# TRACER_JAVA_OPTS: on JDK 23 and newer, leave Scala's LazyVals its sun.misc.Unsafe without a
# warning (older JDKs refuse the option, and 17 to 22 do not warn); and, on Linux when this
# process is not niced, the render's rows below the JIT (tracer_priority).
tracer_java_flags() {
  tracer_flags=()
  if [ "$tracer_java_feature" -ge 23 ]; then tracer_flags+=(--sun-misc-unsafe-memory-access=allow); fi
  tracer_priority=false
  if tracer_unniced; then
    # Perf: the render's row tasks take the lowest Java priority (Renderer), and these options
    # make it nice 4 while every other Java priority, the compiler threads' and the VM thread's
    # stay at nice 0, so while the JIT compiles the render's code on a machine whose processors
    # the rows fill, its threads come first and the compiled code arrives sooner (whole runs:
    # the gallery's showcase 389 -> 344 ms, solids 1332 -> 1287, 720p mesh-20000 920 -> 854;
    # docs/performance.md, round 30). Only when not niced: the JVM sets these values, not
    # offsets, so a niced run keeps its own niceness everywhere instead. A user other than root
    # may lower a priority but not raise one, which is all this asks; the JVM still warns such a
    # user on its standard error, and tracer_launch drops that line (tracer_unwarn).
    tracer_priority=true
    tracer_flags+=(-XX:ThreadPriorityPolicy=1 -XX:JavaPriority1_To_OSPriority=4
      -XX:JavaPriority6_To_OSPriority=0 -XX:JavaPriority7_To_OSPriority=0
      -XX:JavaPriority8_To_OSPriority=0 -XX:JavaPriority9_To_OSPriority=0
      -XX:JavaPriority10_To_OSPriority=0 -XX:CompilerThreadPriority=0 -XX:VMThreadPriority=0)
  fi
}

# tracer_unniced: true on Linux when this process's nice value is 0 (read from /proc, no process
# started); false elsewhere or when it cannot be read.
tracer_unniced() {
  local stat fields
  case "${OSTYPE:-}" in linux*) ;; *) return 1 ;; esac
  IFS= read -r stat </proc/$$/stat 2>/dev/null || return 1
  # The fields after the command's name, which is in parentheses and may hold spaces: state,
  # then 15 more, then the nice value.
  read -r -a fields <<<"${stat##*) }"
  [ "${fields[16]:-}" = 0 ]
}

# tracer_cksums A B C: sets tracer_sums to a short stable number (POSIX cksum) for each of the
# three texts, for file names: one cksum process for all three (each text a here-string on a file
# descriptor, so no subshell is started either).
tracer_cksums() {
  local out line
  tracer_sums=()
  [ $# -eq 3 ] || return 1
  out=$(cksum /dev/fd/3 /dev/fd/4 /dev/fd/5 3<<<"$1" 4<<<"$2" 5<<<"$3") || return 1
  while IFS=' ' read -r line _; do tracer_sums+=("$line"); done <<<"$out"
}

# tracer_jar_dir JAR: sets tracer_jar_dir, the absolute directory of JAR (as the path names it).
tracer_jar_dir() {
  case "$1" in
    */*) tracer_jar_dir=${1%/*} tracer_jar_dir=${tracer_jar_dir:-/} ;;
    *) tracer_jar_dir=. ;;
  esac
  case "$tracer_jar_dir" in
    /*) ;;
    *) tracer_jar_dir=$PWD/$tracer_jar_dir ;;
  esac
}

# tracer_cache JAR TRAINING_DIR...: sets tracer_cache_flags, the JVM options that use the
# start-up cache for this Java, these JVM options and this jar, making the cache first when it is
# missing. On JDK 25 and newer the cache is an AOT cache (JEP 483/514/515: classes loaded and
# linked, and method profiles, from a training run); on 17 to 24 an AppCDS archive of the
# classes the training run loaded. Its file name holds what it depends on (the Java's version
# and path, the JVM's options, the jar's size and time, the training scenes), so a changed jar,
# Java or training scene finds no file and makes a new one, and the old one of that Java is deleted. A cache that cannot be made is
# remembered (a .failed file of the same name), so a failing training run is not repeated on
# every start. Nothing here ever stops a render: on any failure the flags stay empty, and the
# JVM is told to use a cache only if it can (-Xshare:auto, AOTMode auto) and to say nothing.
tracer_cache() {
  local jar=$1
  shift
  tracer_cache_flags=()
  [ "${TRACER_CACHE:-auto}" != off ] || return 0
  [ "$tracer_java_feature" -ge "$tracer_min_java" ] || return 0
  local kind=jsa
  if [ "$tracer_java_feature" -ge 25 ] && [ "${TRACER_CACHE:-auto}" != cds ]; then kind=aot; fi
  # Perf: one stat for the jar and every training scene, one cksum for the three numbers of the
  # name: a process costs 1 to 2 ms, and every render starts here (docs/performance.md, round 13).
  local files=("$jar") entry training dir file listing stamp user
  for dir in "$@"; do
    for entry in "$dir"/*.xml "$dir"/path/*.xml; do
      if [ -e "$entry" ]; then files+=("$entry"); fi
    done
  done
  listing=$(stat -L -c '%s %Y %n' -- "${files[@]}" 2>/dev/null) || true
  # The jar's line comes first: its size and time, then the training scenes' lines.
  stamp=${listing%%$'\n'*}
  local size=${stamp%% *} rest=${stamp#* }
  [ "${rest#* }" = "$jar" ] || return 0
  stamp=$size-${rest%% *}
  training=''
  case "$listing" in *$'\n'*) training=${listing#*$'\n'} ;; esac
  tracer_jar_dir "$jar"
  local dirs=("$tracer_jar_dir")
  user=${XDG_CACHE_HOME:-${HOME:+$HOME/.cache}}
  tracer_cksums "$tracer_java_home|$tracer_java_version|${tracer_jvm[*]}|$tracer_training_width" "$training" \
    "$tracer_jar_dir/${jar##*/}" || return 0
  local name="tracer-java$tracer_java_version-${tracer_sums[0]}-jar$stamp-training${tracer_sums[1]}.$kind"
  # Beside the jar, then in the user's cache directory under a name of its own for each jar.
  if [ -n "$user" ]; then dirs+=("$user/tracer/jar-${tracer_sums[2]}"); fi
  # A cache already made in any of the places is used as it is.
  for dir in ${dirs[@]+"${dirs[@]}"}; do
    if [ -f "$dir/$name" ]; then
      tracer_cache_use "$kind" "$dir/$name"
      return 0
    fi
  done
  # Else it is made in the first place that can take it, unless it failed there before.
  for dir in ${dirs[@]+"${dirs[@]}"}; do
    if [ -f "$dir/$name.failed" ]; then return 0; fi
    if { [ -d "$dir" ] || mkdir -p -- "$dir" 2>/dev/null; } && [ -w "$dir" ]; then
      file=$dir/$name
      tracer_cache_make "$kind" "$jar" "$file" "$@" || true
      if [ -f "$file" ]; then tracer_cache_use "$kind" "$file"; fi
      return 0
    fi
  done
}

# tracer_cache_use KIND FILE: sets tracer_cache_flags to use FILE quietly, if it can be used.
tracer_cache_use() {
  # aot*, every tag set under aot: JDK 25.0.3 writes an aot+codecache+stubs warning to standard
  # output when the names of two of its cached adapters collide (it then makes that adapter
  # afresh; nothing else changes).
  if [ "$1" = aot ]; then
    tracer_cache_flags=(-XX:AOTCache="$2" -Xlog:aot*=off -Xlog:cds=off)
  else
    tracer_cache_flags=(-XX:SharedArchiveFile="$2" -Xshare:auto -Xlog:cds=off -Xlog:cds+dynamic=off)
  fi
}

# tracer_cache_make KIND JAR FILE TRAINING_DIR...: the training run: renders the first training
# scene as one small picture from standard input, then every training scene in one batch
# (tracer.cli.Training: the two ways users' renders run, in one process), then writes the cache
# to FILE. One process at a time makes a given cache (a lock directory beside it; the others go on
# without one); the file appears whole or not at all.
tracer_cache_make() {
  local kind=$1 jar=$2 file=$3
  shift 3
  local lock=$file.lock
  if ! mkdir -- "$lock" 2>/dev/null; then
    # Another process is making it; a lock older than 10 minutes was left by one that died.
    if [ -n "$(find "$lock" -maxdepth 0 -mmin +10 2>/dev/null)" ]; then
      rmdir -- "$lock" 2>/dev/null || true
    fi
    return 1
  fi
  local work status=0
  work=$(mktemp -d "${TMPDIR:-/tmp}/tracer-training.XXXXXX") || {
    rmdir -- "$lock"
    return 1
  }
  tracer_training_list "$work" "$@" >"$work/list" || status=1
  # Older caches of this Java (another jar, other options) in this place are of no more use.
  rm -f -- "${file%-jar*}"-jar*."$kind"
  if [ "$status" = 0 ]; then
    if [ "$kind" = aot ]; then
      # JEP 514: the training run writes the cache when it exits (a second JVM assembles it).
      "$tracer_java" ${tracer_flags[@]+"${tracer_flags[@]}"} "${tracer_jvm[@]}" \
        -XX:AOTCacheOutput="$work/cache.aot" -Xlog:aot*=off -Xlog:cds=off \
        -cp "$jar" tracer.cli.Training "$tracer_training_width" "$work/list" >/dev/null 2>&1 &&
        [ -s "$work/cache.aot" ] && mv -f -- "$work/cache.aot" "$file.partial" || status=1
    else
      "$tracer_java" ${tracer_flags[@]+"${tracer_flags[@]}"} "${tracer_jvm[@]}" \
        -XX:DumpLoadedClassList="$work/classes" \
        -cp "$jar" tracer.cli.Training 64 "$work/list" >/dev/null 2>&1 &&
        "$tracer_java" ${tracer_flags[@]+"${tracer_flags[@]}"} "${tracer_jvm[@]}" \
          -Xshare:dump -XX:SharedClassListFile="$work/classes" \
          -XX:SharedArchiveFile="$file.partial" -Xlog:cds=off -Xlog:cds+dynamic=off \
          -cp "$jar" >/dev/null 2>&1 && [ -s "$file.partial" ] || status=1
    fi
  fi
  if [ "$status" = 0 ]; then
    mv -f -- "$file.partial" "$file" || status=1
  fi
  if [ "$status" != 0 ]; then
    rm -f -- "$file.partial"
    : >"$file.failed" 2>/dev/null || true
  fi
  rm -rf -- "$work"
  rmdir -- "$lock" 2>/dev/null || true
  return "$status"
}

# tracer_training_list WORK TRAINING_DIR...: prints the training run's batch list: every *.xml of
# the TRAINING_DIRs, each to a picture in WORK; and every *.xml of their path/ folders path-traced
# (a frame's own options), to .png and .pfm.
tracer_training_list() {
  local work=$1 dir scene n=0
  shift
  for dir in "$@"; do
    for scene in "$dir"/*.xml; do
      if [ -f "$scene" ]; then
        n=$((n + 1))
        printf '%s\t%s\n' "$scene" "$work/frame-$n.png"
      fi
    done
    for scene in "$dir"/path/*.xml; do
      if [ -f "$scene" ]; then
        n=$((n + 1))
        printf '%s\t%s\t-m path -s 2\n' "$scene" "$work/frame-$n.png" "$scene" "$work/frame-$n.pfm"
      fi
    done
  done
  [ "$n" -gt 0 ]
}

# tracer_launch JAR TRAINING_DIR... -- ARGS...: chooses the Java, prepares its cache and replaces
# this shell with the tracer.
tracer_launch() {
  local jar=$1 training=()
  shift
  while [ $# -gt 0 ] && [ "$1" != -- ]; do
    training+=("$1")
    shift
  done
  if [ $# -gt 0 ]; then shift; fi
  tracer_choose_java || exit 1
  tracer_java_flags
  # The JVM's options: the serial collector, because renders make short-lived garbage fast and on
  # a small machine the serial young collection clears it as quickly as G1 or ParallelGC while
  # keeping the heap (and so the resident memory) small: a 3840x2160 render peaks at 344 MB
  # instead of 1.1 GB (docs/performance.md); and no loop unrolling by C2: the render's loops run a
  # handful of times a call (a node's four children, a combination's parts), unrolling them buys
  # nothing in the compiled code and costs compile time on the one C2 thread of a small machine,
  # while the render waits in slower code (round 16: the gallery's solids 7% and 1280x720 few 16%
  # sooner, steady state and 4K unchanged); and no compilation on stack of a loop in the code
  # that C1 compiles from the start-up cache's profiles (tier 2; the count of its loops' turns is
  # checked every 2^30 turns, not every 2^14): the render's hot methods run short loops millions
  # of times, so that count asked C2 for a version entered in the middle of the loop (about 20 in
  # a run of the solids, 0.19 s of the one C2 thread) just before the ordinary version that makes
  # it useless (round 31: the solids, the showcase and the 720p meshes 5-11% sooner). A long
  # loop of such a method runs in C1's code until the method is called again; the loops of a
  # large mesh's build run in C1's profiling code (tier 3) and keep their on-stack versions.
  # TRACER_JAVA_OPTS replaces them.
  read -r -a tracer_jvm <<<"${TRACER_JAVA_OPTS:-$tracer_default_jvm}"
  # With its own options the JVM halts at the end instead of exiting (tracer.cli.Main.main): an
  # exit first loads the JDK's logging for one debug message, 15-20 ms of every run. Options of the
  # user's may start a flight recording or an agent whose shutdown hooks must run: no halt then.
  if [ -z "${TRACER_JAVA_OPTS+set}" ]; then tracer_jvm+=(-Dtracer.exit=halt); fi
  case "${TRACER_CACHE-}" in
    '' | off | cds) ;;
    *)
      echo "tracer: TRACER_CACHE='$TRACER_CACHE' must be off or cds (or unset)" >&2
      exit 2
      ;;
  esac
  case "${TRACER_LANES:-off}" in
    off) ;;
    # The walks test four boxes at once with the Vector API (docs/performance.md, round 15); its
    # module is incubating, so the JVM must be told to load it. Vector code runs very slowly until
    # C2 compiles it, so C2 compiles the four-box walks 20 times sooner and keeps every branch
    # instead of trapping the ones its first profile did not see (a trap sends the walk back to the
    # interpreter until it is compiled again). Part of the cache's name.
    on)
      tracer_jvm+=(--add-modules jdk.incubator.vector -Dtracer.lanes=on -XX:PerMethodTrapLimit=0
        -XX:CompileCommand=quiet
        "-XX:CompileCommand=CompileThresholdScaling,tracer.render.BvhLanes::*,0.05"
        "-XX:CompileCommand=CompileThresholdScaling,tracer.render.MeshLanes::*,0.05")
      ;;
    *)
      echo "tracer: TRACER_LANES='$TRACER_LANES' must be on or off" >&2
      exit 2
      ;;
  esac
  tracer_cache "$jar" ${training[@]+"${training[@]}"}
  # The JVM's warnings on its standard error that no option silences, in the order it writes
  # them at its start: for a user other than root, that the priorities may not all be set; with
  # the Vector API, that an incubating module is in use.
  local warnings=()
  if $tracer_priority && [ "${EUID:-0}" != 0 ]; then
    warnings+=('*warning: -XX:ThreadPriorityPolicy=1 may require system level permission*')
  fi
  if [ "${TRACER_LANES:-off}" = on ]; then
    warnings+=('WARNING: Using incubator modules: jdk.incubator.vector')
  fi
  if [ ${#warnings[@]} -gt 0 ]; then
    # The JVM's standard error goes through tracer_unwarn, which drops those lines. The tracer is
    # told whether the real standard error is a terminal (for its progress line). The launcher
    # waits for the filter too, so every line is written before it exits.
    local terminal=false status=0 filter unwarned
    if [ -t 2 ]; then terminal=true; fi
    exec {unwarned}> >(tracer_unwarn "${warnings[@]}")
    filter=$!
    "$tracer_java" ${tracer_cache_flags[@]+"${tracer_cache_flags[@]}"} \
      ${tracer_flags[@]+"${tracer_flags[@]}"} "${tracer_jvm[@]}" -Dtracer.terminal="$terminal" \
      -jar "$jar" "$@" 2>&"$unwarned" || status=$?
    exec {unwarned}>&-
    wait "$filter" 2>/dev/null || true
    exit "$status"
  fi
  exec "$tracer_java" ${tracer_cache_flags[@]+"${tracer_cache_flags[@]}"} \
    ${tracer_flags[@]+"${tracer_flags[@]}"} "${tracer_jvm[@]}" -jar "$jar" "$@"
}

# tracer_unwarn PATTERN...: copies standard input to standard error, less the JVM's start-up
# warnings: the first line matching each glob PATTERN (the JVM writes each once, at its start,
# before the tracer writes anything); once all are dropped the rest passes as it comes (cat),
# unfinished lines such as the progress line included.
tracer_unwarn() {
  local line pattern dropped left
  while [ $# -gt 0 ]; do
    if ! IFS= read -r line; then
      # The end before every warning came: an unfinished last line passes as it is.
      if [ -n "$line" ]; then printf '%s' "$line" >&2; fi
      return 0
    fi
    dropped=false left=()
    for pattern in "$@"; do
      # shellcheck disable=SC2053 # the pattern is a glob on purpose
      if ! $dropped && [[ $line == $pattern ]]; then dropped=true; else left+=("$pattern"); fi
    done
    $dropped || printf '%s\n' "$line" >&2
    set -- ${left[@]+"${left[@]}"}
  done
  exec cat >&2
}
