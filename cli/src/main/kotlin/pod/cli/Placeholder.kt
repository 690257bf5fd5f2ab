package pod.cli
