// strata_lod's sources are the other files in this folder; this one keeps the library non-empty
// while it is being filled.
namespace strata::lod {
int libraryVersion() { return 1; }
}  // namespace strata::lod
