"""The board and the link: serial protocol, pyserial link, port discovery and the virtual MinSeg."""
