package pod.core
