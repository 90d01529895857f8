// A generated whole-body CT segmentation for the scaling benchmark: what a user meshing a hundred
// CT scans gives the tool, at a CT's size.
#ifndef CtLikeLabelMap_h
#define CtLikeLabelMap_h

#include "PhantomGrid.h"

namespace slicemesh
{

/** 512 x 512 x 400 voxels of 0.9766 x 0.9766 x 1.25 mm, 87 labels: a body (an elliptic cylinder 460
 *  x 320 mm) inside a 2 mm skin; lungs, heart, spleen; a liver cut into 8 touching segments;
 *  kidneys inside their cortex; a hollow stomach and bladder; 23 vertebral bodies stacked touching;
 *  24 curved ribs 7 mm thick; a spinal canal, an aorta and a vena cava running through the body
 *  past its ends; a thin helical vessel; a bowel of random turns; 10 lymph nodes; 4 labels of one
 *  to three voxels (outside the body). Each organ replaces the body's voxels where it lies, so the
 *  body is one large piece with a cavity for most organs. */
MaskVolume::Pointer ctLikeLabelMap();

} // namespace slicemesh

#endif
