/*
 * Volume images into 3D textures (doc/volumes.md, "Files"): the file is
 * checked as every reader of libsample_io checks it (a regular file, the
 * header pre-flights), its slices read by OpenImageIO (oiio_volume.cpp),
 * and the texture made by sample_texture_create_3d.
 */
#include "io_internal.h"

#include <stdlib.h>

sample_status sample_io_read_volume(const char *path, const sample_mip_params *mip, sample_texture **out,
                                    sample_error *err)
{
    io_volume v;
    sample_volume vol;
    sample_status st;
    if (!out) return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "sample_io_read_volume: out is NULL");
    *out = NULL;
    if (!path || !*path) return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "sample_io_read_volume: no path");
    if ((st = sample_io_check_regular_file(path, "volume", err)) != SAMPLE_OK) return st;
    if ((st = io_preflight(path, NULL, 0, err)) != SAMPLE_OK) return st;
    if ((st = io_oiio_read_volume(path, &v, err)) != SAMPLE_OK) return st;
    vol.width = v.width;
    vol.height = v.height;
    vol.depth = v.depth;
    vol.channels = v.channels;
    vol.format = SAMPLE_FORMAT_F32;
    vol.data = v.data;
    vol.row_stride = 0;
    vol.slice_stride = 0;
    st = sample_texture_create_3d(&vol, mip, out, err);
    free(v.data);
    return st;
}
