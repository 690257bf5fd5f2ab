package pod.sim
