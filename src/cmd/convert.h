/* convert.h — the command `pathlab convert IN.pfm|IN.hdr OUT.png|OUT.ppm|OUT.pfm [--exposure STOPS]`:
 * a PFM (e.g. a --split layer) or a Radiance .hdr made viewable or a PFM, and its size and each channel's mean, min and max.
 * An input holding a NaN or an infinity is still shown (black in a picture), with a warning naming the first. */
#ifndef PATHLAB_CONVERT_H
#define PATHLAB_CONVERT_H

/* Exit status 0, 1 when the write failed, 2 for bad arguments or an unreadable input. */
int convert_main(int argc, char **argv);
#endif
