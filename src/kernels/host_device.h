// ETD-DPD: ETD_HOST_DEVICE marks the kernels' functions that also run on a GPU (the pair law,
// its weights and its noise), for the KOKKOS styles built for CUDA or HIP; elsewhere it is empty.
#ifndef ETD_HOST_DEVICE_H
#define ETD_HOST_DEVICE_H

#if defined(__CUDACC__) || defined(__HIPCC__)
#define ETD_HOST_DEVICE __host__ __device__
// Random123's generators compile for both sides (by default only for the device side)
#ifndef R123_CUDA_DEVICE
#define R123_CUDA_DEVICE __host__ __device__
#endif
#else
#define ETD_HOST_DEVICE
#endif

#endif
