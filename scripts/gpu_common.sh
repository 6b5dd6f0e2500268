# Sourced by the GPU scripts (gpu_check.sh, gpu_diag.sh, gpu_diag_repeat.sh): what each needs to
# run a bundle made by gpu_pack.sh, and a report folder that replaces only its own kind.

# Exports what the bundle's programs need: its libraries and shaders, NVIDIA's EGL vendor file
# where the driver has one, and EGL_PLATFORM (Mesa needs surfaceless without a display; strata
# asks NVIDIA's EGL for its device platform itself).
use_gpu_bundle() {  # BUNDLE (absolute)
    export LD_LIBRARY_PATH=$1/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH} STRATA_SHADER_DIR=$1/shaders
    export EGL_PLATFORM=${EGL_PLATFORM:-surfaceless}
    local v
    for v in /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json /usr/share/glvnd/egl_vendor.d/10_nvidia.json; do
        [[ -z ${__EGL_VENDOR_LIBRARY_FILENAMES-} && -e $v ]] && export __EGL_VENDOR_LIBRARY_FILENAMES=$v
    done
    return 0
}

# Makes OUT afresh and prints its absolute path. An old report of this kind (it holds MARKER) is
# replaced; any other non-empty folder is refused, so a mistyped path deletes nothing.
fresh_report_folder() {  # SCRIPT-NAME OUT MARKER
    local script=$1 out=$2 marker=$3
    if [[ -e $out && -n $(ls -A "$out" 2>/dev/null) && ! -e $out/$marker ]]; then
        echo "$script: $out exists and is not a report of $script; give another folder" >&2
        return 1
    fi
    rm -rf "$out" && mkdir -p "$out" && touch "$out/$marker" && realpath "$out"
}
