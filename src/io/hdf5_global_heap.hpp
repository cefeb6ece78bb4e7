#pragma once
// Variable-length strings checked before HDF5 reads them (issue 14, fuzzing of the snapshot and
// checkpoint readers). HDF5 keeps such a string in the file's "global heap": the attribute or
// dataset holds, per string, its length, the file address of a heap collection and the object's
// index in it. Reading the string makes HDF5 1.10 decode that collection (H5HG_read, through
// H5Aread / H5Dread), and a damaged collection is trusted there: an object of index 0 and size 0
// loops for ever (the decoding loop does not advance), an object size near 2^64 wraps the loop
// backwards (for ever again), a collection size of 2^47 is allocated as it stands, and an object
// longer than the string's length is copied past the end of the buffer sized by that length.
// No HDF5 call before the read sees any of this, so this check reads the stored references
// without dereferencing them (a conversion to an opaque type that keeps the stored bytes) and
// walks each collection they name, from the file's own bytes, exactly as HDF5 will (HDF5 file
// format specification, section III.E "Global Heap"); anything HDF5 would loop on, over-allocate
// for or overrun is refused with a FileError naming the file, the object and what is wrong.
#include <hdf5.h>

#include <cstddef>
#include <string>

namespace trapdem {

// `object` is an open attribute (`attribute` true) or dataset of variable-length strings with
// `count` elements; `where` names it in messages ("<file>: /path: attribute 'stage'").
void check_global_heap_strings(hid_t object, bool attribute, std::size_t count, const std::string& where);

}  // namespace trapdem
