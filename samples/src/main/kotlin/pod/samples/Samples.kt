package pod.samples
